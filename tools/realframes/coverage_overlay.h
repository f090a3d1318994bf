#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "vision/camera_model.h"

namespace houghloc {

/// Where a frame's points cover the map's visible lines (groundtruth_metrics.h), drawn on its
/// image: each visible line sample (robot frame, on the ground) green when a point lies within
/// radius_m of it and red when none does, and each point blue; all projected with `camera` (the
/// pose the vision used, so that the samples land on the image's lines where the pose and the
/// ground truth are right). A caption gives the covered share. `bgr` is not changed.
cv::Mat coverageOverlay(const cv::Mat& bgr, const CameraModel& camera,
                        const std::vector<Eigen::Vector2d>& samples_robot,
                        const std::vector<Eigen::Vector2d>& points_robot, double radius_m);

/// coverageOverlay written to `path` (PNG; its folder is created). Throws RecordingError when the
/// file cannot be written.
void writeCoverageOverlay(const std::string& path, const cv::Mat& bgr, const CameraModel& camera,
                          const std::vector<Eigen::Vector2d>& samples_robot,
                          const std::vector<Eigen::Vector2d>& points_robot, double radius_m);

/// The colours coverageOverlay draws with (BGR).
inline const cv::Scalar kCoveredColour(0, 200, 0), kUncoveredColour(0, 0, 255),
    kPointColour(255, 80, 0);

}  // namespace houghloc
