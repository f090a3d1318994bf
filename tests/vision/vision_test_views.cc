#include "vision_test_views.h"

#include <algorithm>
#include <map>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <tuple>

#include "field_models/field_distance.h"
#include "field_models/standard_fields.h"
#include "vision/camera_model.h"

namespace houghloc::testing {

const TestView& testView(const std::string& preset, const std::string& field, const Pose2& pose,
                         const SyntheticStyle& style) {
  static std::map<std::string, TestView> cache;
  std::ostringstream key;
  key << preset << '|' << field << '|' << pose.x << ',' << pose.y << ',' << pose.theta << '|'
      << style.gradient << ',' << style.noise_sigma << ',' << style.seed;
  for (const cv::Vec3b& colour : {style.turf, style.line, style.background}) {
    key << ',' << int(colour[0]) << ' ' << int(colour[1]) << ' ' << int(colour[2]);
  }
  auto it = cache.find(key.str());
  if (it != cache.end()) return it->second;
  TestView view;
  view.preset = cameraPreset(preset);
  view.field = makeStandardField(field);
  view.field_T_robot = pose;
  const CameraModel camera(view.preset.intrinsics, view.preset.robot_T_camera);
  view.image = drawFieldView(camera, view.field, pose, style);
  return cache.emplace(key.str(), std::move(view)).first->second;
}

PointScore scorePoints(const TestView& view, const std::vector<Eigen::Vector2d>& p_robot,
                       double max_distance_m) {
  PointScore score;
  std::vector<double> errors;
  for (const Eigen::Vector2d& p : p_robot) {
    errors.push_back(nearestFeature(view.field, view.field_T_robot.transform(p)).distance_m);
  }
  score.points = errors.size();
  if (errors.empty()) return score;
  score.precision =
      static_cast<double>(std::count_if(errors.begin(), errors.end(),
                                        [&](double e) { return e <= max_distance_m; })) /
      errors.size();
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  score.median_error_m = errors[errors.size() / 2];
  return score;
}

cv::Mat turfTexture(cv::Size size, int seed) {
  cv::Mat noise(size, CV_32F);
  cv::RNG rng(static_cast<uint64_t>(seed));
  rng.fill(noise, cv::RNG::NORMAL, 0.0, 1.0);
  cv::GaussianBlur(noise, noise, cv::Size(), 2.0);
  cv::Scalar mean, stddev;
  cv::meanStdDev(noise, mean, stddev);
  return noise / stddev[0];
}

VisionRun runVision(const TestView& view, const cv::Mat& image, VisionConfig config, double far_m) {
  config.line_width_m = view.field.line_width;
  VisionPipeline pipeline(view.preset.intrinsics, config);
  VisionRun run;
  run.points = pipeline.process(image, view.preset.robot_T_camera).ground.points;
  std::vector<Eigen::Vector2d> p_robot;
  for (const GroundPoint& p : run.points) {
    p_robot.push_back(p.p_robot);
    run.far += p.p_robot.norm() >= far_m;
  }
  run.score = scorePoints(view, p_robot);
  return run;
}

}  // namespace houghloc::testing
