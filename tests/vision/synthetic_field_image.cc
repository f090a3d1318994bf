#include "synthetic_field_image.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

#include "field_models/field_distance.h"

namespace houghloc::testing {

cv::Mat drawFieldView(const CameraModel& camera, const FieldModel& field, const Pose2& field_T_robot,
                      const SyntheticStyle& style) {
  cv::Mat image(camera.height(), camera.width(), CV_8UC3);
  const Pose3& pose = camera.pose();
  const Eigen::Vector3d origin = pose.translation();
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      const Eigen::Vector3d ray = camera.pixelRay(u, v);
      const Eigen::Vector3d ray_right = camera.pixelRay(u + 1, v);
      const Eigen::Vector3d ray_down = camera.pixelRay(u, v + 1);
      cv::Vec3f colour = style.background;
      if (ray.allFinite() && ray.z() < -1e-4) {
        const Eigen::Vector2d p_robot = (origin - origin.z() / ray.z() * ray).head<2>();
        const Eigen::Vector2d p_field = field_T_robot.transform(p_robot);
        if (std::abs(p_field.x()) <= field.outerHalfLength() &&
            std::abs(p_field.y()) <= field.outerHalfWidth()) {
          // Pixel footprint on the ground (m): anti-aliasing width of the line edges.
          double footprint = 0.01;
          if (ray_right.z() < -1e-4 && ray_down.z() < -1e-4) {
            const Eigen::Vector3d right = origin - origin.z() / ray_right.z() * ray_right;
            const Eigen::Vector3d down = origin - origin.z() / ray_down.z() * ray_down;
            footprint = std::max((right.head<2>() - p_robot).norm(), (down.head<2>() - p_robot).norm());
          }
          const double distance = nearestFeature(field, p_field).distance_m;
          const double coverage =
              std::clamp((0.5 * field.line_width - distance) / std::max(footprint, 1e-4) + 0.5, 0.0, 1.0);
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
