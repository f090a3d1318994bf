#pragma once

#include <opencv2/core.hpp>

#include "field_models/ground_points.h"
#include "field_models/pose3.h"
#include "vision/camera_model.h"

namespace houghloc {

/// What a team would write with stock OpenCV (issue 5 baseline): undistort the whole image, HSV
/// inRange masks for white and green, keep white near green, Canny, HoughLinesP, and project
/// points sampled along each segment (every 4 px) to the ground.
class OpenCvLineBaseline {
 public:
  OpenCvLineBaseline(const CameraIntrinsics& intrinsics);
  GroundPoints process(const cv::Mat& bgr, const Pose3& robot_T_camera);

 private:
  CameraIntrinsics intrinsics_;
  cv::Mat map_x_, map_y_;
};

}  // namespace houghloc
