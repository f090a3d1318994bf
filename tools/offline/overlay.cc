#include "tools/offline/overlay.h"

#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace houghloc {
namespace {

void drawRowCurve(cv::Mat* image, const std::vector<float>& rows, const cv::Scalar& colour) {
  std::vector<cv::Point> curve;
  for (size_t u = 0; u < rows.size(); ++u) {
    if (std::isfinite(rows[u]) && rows[u] >= 0.f && rows[u] < image->rows) {
      curve.emplace_back(static_cast<int>(u), static_cast<int>(std::lround(rows[u])));
    } else if (!curve.empty()) {
      cv::polylines(*image, curve, false, colour, 1, cv::LINE_AA);
      curve.clear();
    }
  }
  if (!curve.empty()) cv::polylines(*image, curve, false, colour, 1, cv::LINE_AA);
}

}  // namespace

cv::Mat drawVisionOverlay(const cv::Mat& bgr, const VisionResult& result,
                          const CameraModel& camera) {
  cv::Mat image = bgr.clone();
  drawRowCurve(&image, std::vector<float>(result.horizon_rows.begin(), result.horizon_rows.end()),
               {0, 255, 255});
  if (result.boundary.found) drawRowCurve(&image, result.boundary.rows, {255, 0, 255});
  for (const LineSpot& spot : result.spots) {
    cv::circle(image, {static_cast<int>(spot.pixel.x()), static_cast<int>(spot.pixel.y())}, 1,
               spot.vertical_scan ? cv::Scalar(0, 0, 255) : cv::Scalar(255, 0, 0), -1);
  }
  for (const GroundPoint& p : result.ground.points) {
    cv::circle(image, {static_cast<int>(p.pixel.x()), static_cast<int>(p.pixel.y())}, 3,
               {0, 220, 0}, 1, cv::LINE_AA);
  }
  for (const GroundSegment& s : result.features.segments) {
    const auto a = camera.project({s.a.x(), s.a.y(), 0.0});
    const auto b = camera.project({s.b.x(), s.b.y(), 0.0});
    if (a && b) {
      cv::line(image, {static_cast<int>(a->x()), static_cast<int>(a->y())},
               {static_cast<int>(b->x()), static_cast<int>(b->y())}, {255, 255, 0}, 1, cv::LINE_AA);
    }
  }
  // Field-edge samples: a cross where the carpet's end was seen, with its range in metres.
  for (const FieldEdgePoint& e : result.ground.field_edge) {
    const auto pixel = camera.project({e.p_robot.x(), e.p_robot.y(), 0.0});
    if (!pixel) continue;
    const cv::Point at(static_cast<int>(pixel->x()), static_cast<int>(pixel->y()));
    cv::drawMarker(image, at, {0, 140, 255}, cv::MARKER_CROSS, 9, 1, cv::LINE_AA);
    char range[16];
    std::snprintf(range, sizeof(range), "%.1f", e.p_robot.norm());
    cv::putText(image, range, at + cv::Point(4, -4), cv::FONT_HERSHEY_PLAIN, 0.8, {0, 140, 255});
  }
  char text[128];
  std::snprintf(text, sizeof(text), "%zu pts  %.2f ms  corr r %.2f p %.2f deg",
                result.ground.points.size(), result.diagnostics.time_total_ms,
                result.diagnostics.pose_correction_rad.x() * 57.29578,
                result.diagnostics.pose_correction_rad.y() * 57.29578);
  cv::putText(image, text, {8, image.rows - 10}, cv::FONT_HERSHEY_SIMPLEX, 0.5, {0, 0, 0}, 3);
  cv::putText(image, text, {8, image.rows - 10}, cv::FONT_HERSHEY_SIMPLEX, 0.5, {255, 255, 255}, 1);
  return image;
}

}  // namespace houghloc
