#include "synthetic_field_image.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <vector>

#include "field_models/field_distance.h"

namespace houghloc::testing {

cv::Mat drawFieldView(const CameraModel& camera, const FieldModel& field,
                      const Pose2& field_T_robot, const SyntheticStyle& style) {
  cv::Mat image(camera.height(), camera.width(), CV_8UC3);
  const Eigen::Vector3d origin = camera.pose().translation();
  // Ground point of every pixel (NaN above the horizon), then colours with the pixel footprint
  // taken from the neighbours as the anti-aliasing width.
  std::vector<Eigen::Vector2d> ground(static_cast<size_t>(image.rows) * image.cols,
                                      Eigen::Vector2d::Constant(std::nan("")));
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      const Eigen::Vector3d ray = camera.pixelRay(u, v);
      if (ray.allFinite() && ray.z() < -1e-4) {
        ground[static_cast<size_t>(v) * image.cols + u] =
            (origin - origin.z() / ray.z() * ray).head<2>();
      }
    }
  }
  const auto at = [&](int u, int v) {
    return ground[static_cast<size_t>(std::min(v, image.rows - 1)) * image.cols +
                  std::min(u, image.cols - 1)];
  };
  NearestFeatureSearch nearest(field);  // nearestFeature(), faster pixel after pixel
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      const Eigen::Vector2d p_robot = at(u, v);
      cv::Vec3f colour = style.background;
      if (p_robot.allFinite()) {
        const Eigen::Vector2d p_field = field_T_robot.transform(p_robot);
        if (std::abs(p_field.x()) <= field.outerHalfLength() &&
            std::abs(p_field.y()) <= field.outerHalfWidth()) {
          double footprint = 0.01;
          const Eigen::Vector2d right = at(u + 1, v), down = at(u, v + 1);
          if (right.allFinite() && down.allFinite()) {
            footprint = std::max((right - p_robot).norm(), (down - p_robot).norm());
          }
          const double distance = nearest.nearest(p_field).distance_m;
          const double coverage = std::clamp(
              (0.5 * field.line_width - distance) / std::max(footprint, 1e-4) + 0.5, 0.0, 1.0);
          colour = (1.0 - coverage) * cv::Vec3f(style.turf) + coverage * cv::Vec3f(style.line);
        }
      }
      const double light = 1.0 - style.gradient * u / std::max(1, image.cols - 1);
      for (int c = 0; c < 3; ++c) {
        image.at<cv::Vec3b>(v, u)[c] = cv::saturate_cast<uchar>(colour[c] * light);
      }
    }
  }
  if (style.noise_sigma > 0.0) {
    cv::Mat noise(image.size(), CV_32FC3);
    cv::RNG rng(style.seed);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, style.noise_sigma);
    cv::Mat image_f;
    image.convertTo(image_f, CV_32FC3);
    image_f += noise;
    image_f.convertTo(image, CV_8UC3);
  }
  return image;
}

}  // namespace houghloc::testing
