#include "vision/boundary_gap.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace houghloc {

std::vector<SpotRay> dropSpotsNearBoundary(const std::vector<SpotRay>& rays,
                                           const CameraModel& camera, const FieldBoundary& boundary,
                                           const std::vector<int>& start_rows, double min_gap_m,
                                           double min_boundary_range_m, int* dropped) {
  if (dropped) *dropped = 0;
  if (min_gap_m <= 0.0 || !boundary.found || boundary.rows.empty()) return rays;
  // The boundary's ground point per block of columns, computed on demand (one undistortion).
  constexpr int kBlock = 8;
  const int width = static_cast<int>(boundary.rows.size());
  std::vector<std::optional<std::optional<Eigen::Vector2d>>> edge((width + kBlock - 1) / kBlock);
  const GroundProjectionConfig unlimited = unlimitedProjection();
  const GroundProjector projector(camera.pose());
  std::vector<SpotRay> kept;
  kept.reserve(rays.size());
  for (const SpotRay& ray : rays) {
    const int u = std::clamp(static_cast<int>(std::lround(ray.pixel.x())), 0, width - 1);
    auto& cached = edge[static_cast<size_t>(u / kBlock)];
    if (!cached) {
      const int c = std::min(width - 1, (u / kBlock) * kBlock + kBlock / 2);
      const float row = boundary.rowAt(c);
      const int start =
          c < static_cast<int>(start_rows.size()) ? start_rows[static_cast<size_t>(c)] : 0;
      // A boundary at the start row is no seen end of the field, nor is a near one.
      cached = row > static_cast<float>(std::max(start, 0)) + 1.0f ? camera.pixelToGround(c, row)
                                                                   : std::nullopt;
      if (*cached && (*cached)->norm() < min_boundary_range_m) *cached = std::nullopt;
    }
    const auto spot =
        *cached ? projector.project(ray.ray_camera, unlimited) : std::optional<Eigen::Vector2d>{};
    if (spot && (*spot - **cached).norm() < min_gap_m) {
      if (dropped) ++*dropped;
      continue;
    }
    kept.push_back(ray);
  }
  return kept;
}

}  // namespace houghloc
