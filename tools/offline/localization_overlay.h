#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "field_models/field_model.h"
#include "tools/offline/estimate_csv.h"
#include "vision/camera_model.h"
#include "vision/vision_pipeline.h"

namespace houghloc {

/// An overlay of the localization modes: the vision overlay (horizon, field boundary, line points;
/// drawVisionOverlay) plus the map's lines, arcs and marks projected into the image from the best
/// pose (orange), from the ground truth when given (thin grey, for comparison), and a status line
/// at the top: status, best pose, number of hypotheses.
cv::Mat drawLocalizationOverlay(const cv::Mat& bgr, const VisionResult& vision,
                                const CameraModel& camera, const FieldModel& field,
                                const FrameEstimate& estimate,
                                const std::optional<Pose2>& ground_truth);

/// A frame without an image (missing or unreadable): a dark image of the camera's size with the
/// reason and the status line, so a video keeps its timing.
cv::Mat drawMissingFrameOverlay(int width, int height, const std::string& problem,
                                const FrameEstimate& estimate);

/// Projects the map, seen from field_T_robot, into the image: polylines through samples every
/// few centimetres, cut where a sample is behind the camera or outside the image.
void drawProjectedMap(cv::Mat* image, const CameraModel& camera, const FieldModel& field,
                      const Pose2& field_T_robot, const cv::Scalar& colour, int thickness_px);

}  // namespace houghloc
