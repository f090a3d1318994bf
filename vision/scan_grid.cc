#include "vision/scan_grid.h"

#include <algorithm>
#include <cmath>

namespace houghloc {
namespace {

/// First row (from the top) in column u that sees ground within max_range_m of the camera's
/// foot when the camera looks pitch_margin_rad further down than its pose says: bisection on
/// the depression of the pixel's ray below the horizontal.
int rangeLimitRow(const CameraModel& camera, double u, double max_range_m,
                  double pitch_margin_rad) {
  const double height_m = camera.pose().z;
  if (!(height_m > 0.0)) return camera.height();  // no ground below the camera
  // Never above the rays the camera model projects at all (CameraModelConfig).
  const double min_depression = std::max(std::atan2(height_m, max_range_m) - pitch_margin_rad,
                                         camera.config().min_depression_rad);
  const double min_sine = std::sin(min_depression);
  const auto within = [&](int v) {
    const Eigen::Vector3d ray = camera.pixelRay(u, v);  // unit: -z is the depression's sine
    return ray.allFinite() && -ray.z() >= min_sine;
  };
  int lo = 0, hi = camera.height() - 1;
  if (within(lo)) return 0;
  if (!within(hi)) return camera.height();
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    (within(mid) ? hi : lo) = mid;
  }
  return hi;
}

/// step (px) within [min_step, max_step], and at least 1 px whatever a config says (a step of 0
/// would never leave the row it is on).
int clampStep(double step, int min_step, int max_step) {
  const int low = std::max(1, min_step), high = std::max(low, max_step);
  if (!std::isfinite(step)) return low;
  return static_cast<int>(std::clamp(step, 1.0 * low, 1.0 * high));
}

}  // namespace

ScanGrid makeScanGrid(const CameraModel& camera, const LineWidthModel& widths,
                      const FieldBoundary& boundary, const ScanGridConfig& config) {
  ScanGrid grid;
  const int width = camera.width(), height = camera.height();
  const double u_mid = 0.5 * (width - 1);
  // With roll the range limit is tilted: take the most permissive of three probes; every spot
  // is range-checked again when it is projected.
  const auto topRow = [&](double pitch_margin_rad) {
    return std::min({rangeLimitRow(camera, 0.0, config.max_range_m, pitch_margin_rad),
                     rangeLimitRow(camera, u_mid, config.max_range_m, pitch_margin_rad),
                     rangeLimitRow(camera, width - 1.0, config.max_range_m, pitch_margin_rad)});
  };
  grid.top_row = topRow(config.range_pitch_margin_rad);
  // The pitch margin's band (above the range limit at the pose itself) is there for a pose a
  // degree or two off: its scanlines are spaced as at that limit, its rows sparser still.
  const int range_row = topRow(0.0);
  const auto spacingRow = [&](double v) {
    return static_cast<float>(std::max(v, 1.0 * range_row));
  };
  float boundary_top = static_cast<float>(height);
  for (float row : boundary.rows) boundary_top = std::min(boundary_top, row);
  const int first_row = std::max(grid.top_row, static_cast<int>(std::ceil(boundary_top)));
  if (first_row >= height) return grid;

  // Horizontal scanlines: the ground distance between rows is metres-per-px along the column.
  for (double v = height - 1.0; v >= first_row;) {
    grid.rows.push_back(static_cast<int>(v));
    const double m_per_px = widths.metresPerPx(static_cast<float>(u_mid), spacingRow(v)).y();
    const int min_step = v < range_row ? config.margin_row_step_px : config.min_row_step_px;
    v -= clampStep(config.target_spacing_m / m_per_px, min_step, config.max_step_px);
  }

  // Vertical scanlines: level L (every min_step * 2^L px) is needed where the wanted column
  // spacing is below min_step * 2^(L + 1), i.e. from the top down to the row where it reaches it.
  // At most 2^14 px and 16 levels whatever a config says, so that no shift overflows.
  const int min_step = std::clamp(config.min_column_step_px, 1, 1 << 14);
  int max_level = 0;
  constexpr int kMaxLevel = 16;
  while (max_level < kMaxLevel && (min_step << (max_level + 1)) <= config.max_step_px) ++max_level;
  std::vector<int> level_end(static_cast<size_t>(max_level + 1), height);
  for (int level = 0; level < max_level; ++level) {
    int v = first_row;
    while (v < height) {
      const double m_per_px = widths.metresPerPx(static_cast<float>(u_mid), spacingRow(v)).x();
      if (config.target_spacing_m / m_per_px >= (min_step << (level + 1))) break;
      ++v;
    }
    level_end[static_cast<size_t>(level)] = v;
  }
  for (int k = 0; k * min_step < width; ++k) {
    int level = 0;
    while (level < max_level && k % (2 << level) == 0) ++level;
    ScanGrid::Column column;
    column.u = k * min_step;
    column.v_begin = std::max(grid.top_row, static_cast<int>(std::ceil(boundary.rowAt(column.u))));
    column.v_end = level_end[static_cast<size_t>(level)];
    if (column.v_end > column.v_begin) grid.columns.push_back(column);
  }
  return grid;
}

}  // namespace houghloc
