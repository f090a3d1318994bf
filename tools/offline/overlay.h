#pragma once

#include <opencv2/core.hpp>

#include "vision/vision_pipeline.h"

namespace houghloc {

/// The frame with the vision result drawn on it: horizon (yellow), field boundary (magenta),
/// accepted spots (red: vertical scanlines, blue: horizontal), projected points (green rings),
/// fitted segments (cyan) and the frame's numbers in the corner.
cv::Mat drawVisionOverlay(const cv::Mat& bgr, const VisionResult& result,
                          const CameraModel& camera);

}  // namespace houghloc
