#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "field_models/field_model.h"
#include "field_models/pose2.h"
#include "synthetic_field_image.h"
#include "vision/camera_presets.h"
#include "vision/vision_pipeline.h"

namespace houghloc::testing {

/// A synthetic frame with everything needed to score it.
struct TestView {
  CameraPreset preset;
  FieldModel field;
  Pose2 field_T_robot;
  cv::Mat image;
};

/// A view of `field` from `preset`'s camera at field_T_robot, cached per process (drawing a frame
/// takes a few hundred milliseconds).
const TestView& testView(const std::string& preset, const std::string& field, const Pose2& pose,
                         const SyntheticStyle& style = {});

/// Share of the points within max_distance_m of a map line at the view's pose, and their median
/// distance (m).
struct PointScore {
  double precision = 0.0;
  double median_error_m = 0.0;
  size_t points = 0;
};
PointScore scorePoints(const TestView& view, const std::vector<Eigen::Vector2d>& p_robot,
                       double max_distance_m = 0.05);

/// Turf texture: blades and tufts a few px across, as blurred Gaussian noise with a spread of
/// one grey level (CV_32F of `size`; `seed` picks the noise).
cv::Mat turfTexture(cv::Size size, int seed);

/// What the pipeline finds in `image` (a variant of view.image) with `config`, its line width
/// set to the field's: the ground points, their score, and how many lie far_m or further from
/// the robot.
struct VisionRun {
  std::vector<GroundPoint> points;
  PointScore score;
  size_t far = 0;
};
VisionRun runVision(const TestView& view, const cv::Mat& image, VisionConfig config,
                    double far_m = 3.0);

}  // namespace houghloc::testing
