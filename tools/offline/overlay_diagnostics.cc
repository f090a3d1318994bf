#include "tools/offline/overlay_diagnostics.h"

#include <opencv2/imgproc.hpp>

#include "vision/frame_rejection.h"

namespace houghloc {
namespace {

cv::Scalar rejectionColour(SpotRejection reason) {
  switch (reason) {
    case SpotRejection::kTooWide:
      return {0, 140, 255};
    case SpotRejection::kTooNarrow:
      return {200, 0, 160};
    case SpotRejection::kNotGreenBounded:
      return {160, 160, 160};
    case SpotRejection::kNotWhite:
      return {180, 105, 255};
    case SpotRejection::kSoftEdge:
      return {40, 80, 140};
    case SpotRejection::kCompactBlob:
      return {255, 255, 0};
    case SpotRejection::kOnBall:
      return {0, 0, 0};
  }
  return {255, 255, 255};
}

}  // namespace

void drawFrameDiagnostics(cv::Mat* overlay, const cv::Mat& bgr, const VisionResult& result) {
  const FieldColor& colour = result.diagnostics.field_color;
  if (colour.valid && bgr.type() == CV_8UC3) {
    cv::Mat turf(bgr.size(), CV_8U);
    for (int v = 0; v < bgr.rows; ++v) {
      const uchar* p = bgr.ptr<uchar>(v);
      uchar* out = turf.ptr<uchar>(v);
      for (int u = 0; u < bgr.cols; ++u) out[u] = colour.isField(p + 3 * u) ? 255 : 0;
    }
    // Close small gaps (lines, texture) so the outline shows regions, not speckle.
    cv::morphologyEx(turf, turf, cv::MORPH_OPEN, cv::Mat::ones(5, 5, CV_8U));
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(turf, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    cv::drawContours(*overlay, contours, -1, {0, 100, 0}, 1, cv::LINE_AA);
  }
  for (const RejectedSpot& r : result.diagnostics.spot_stats.rejected) {
    cv::circle(*overlay, {static_cast<int>(r.pixel.x()), static_cast<int>(r.pixel.y())}, 1,
               rejectionColour(r.reason), -1);
  }
  const FrameRejection rejection = classifyFrame(result);
  if (rejection != FrameRejection::kNone) {
    cv::putText(*overlay, frameRejectionName(rejection), {8, 16}, cv::FONT_HERSHEY_PLAIN, 1.0,
                {0, 0, 255}, 1, cv::LINE_AA);
  }
}

}  // namespace houghloc
