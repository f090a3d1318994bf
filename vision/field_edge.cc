#include "vision/field_edge.h"

#include <algorithm>
#include <cmath>

namespace houghloc {

std::vector<FieldEdgePoint> fieldEdgePoints(const CameraModel& camera,
                                            const FieldBoundary& boundary,
                                            const std::vector<int>& start_rows, int camera_id,
                                            const FieldEdgeSamplingConfig& config) {
  std::vector<FieldEdgePoint> out;
  const int width = camera.width();
  if (!boundary.found || config.columns < 1 || static_cast<int>(boundary.rows.size()) != width ||
      static_cast<int>(start_rows.size()) != width) {
    return out;
  }
  GroundProjectionConfig limits;
  limits.max_range_m = config.max_range_m;
  limits.min_depression_rad = 0.0;
  const double bottom = camera.height() - 1.0;
  for (int i = 0; i < config.columns; ++i) {
    const int u =
        std::clamp(static_cast<int>(std::lround((i + 0.5) * width / config.columns)), 0, width - 1);
    const double top = boundary.rowAt(u);
    if (!std::isfinite(top) || top <= start_rows[u] + config.min_rows_below_start ||
        top + config.row_sigma_px >= bottom) {
      continue;
    }
    const auto edge = pixelToGround(camera, u, top, limits);
    const auto nearer = pixelToGround(camera, u, top + config.row_sigma_px, limits);
    if (!edge || !nearer) continue;
    out.push_back({*edge, std::abs(edge->norm() - nearer->norm()), camera_id});
  }
  return out;
}

}  // namespace houghloc
