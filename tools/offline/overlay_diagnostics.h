#pragma once

#include <opencv2/core.hpp>

#include "vision/vision_pipeline.h"

namespace houghloc {

/// Draws on an overlay what tells a team at a new venue what went wrong: the outline of the
/// pixels taken for turf (dark green), rejected spot candidates by reason (orange too wide,
/// purple too narrow, grey not turf-bounded, pink not white, brown soft edge; needs
/// LineSpotConfig::keep_rejected) and, on a frame without points, the reason in the top row.
/// bgr: the frame's image (BGR8).
void drawFrameDiagnostics(cv::Mat* overlay, const cv::Mat& bgr, const VisionResult& result);

}  // namespace houghloc
