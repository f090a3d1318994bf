#include "field_models/distance_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "field_models/field_distance.h"

namespace houghloc {

DistanceGrid::DistanceGrid(const FieldModel& field, const DistanceGridConfig& config)
    : config_(config) {
  if (!(config.resolution_m > 0.0)) throw std::invalid_argument("resolution_m must be > 0");
  const double hx = field.outerHalfLength() + config.margin_m;
  const double hy = field.outerHalfWidth() + config.margin_m;
  origin_ = Eigen::Vector2d(-hx, -hy);
  inv_resolution_ = 1.0 / config.resolution_m;
  cols_ = static_cast<int>(std::ceil(2.0 * hx / config.resolution_m)) + 1;
  rows_ = static_cast<int>(std::ceil(2.0 * hy / config.resolution_m)) + 1;
  last_col_ = cols_ - 1.0;
  last_row_ = rows_ - 1.0;
  values_.resize(static_cast<size_t>(cols_) * rows_);
  NearestFeatureSearch search(field);
  for (int r = 0; r < rows_; ++r) {
    for (int c = 0; c < cols_; ++c) {
      const Eigen::Vector2d p = origin_ + config.resolution_m * Eigen::Vector2d(c, r);
      const double d = search.nearest(p).distance_m;
      values_[static_cast<size_t>(r) * cols_ + c] =
          static_cast<float>(std::min(d, config.max_distance_m));
    }
  }
  buildBlockMinima();
}

void DistanceGrid::buildBlockMinima() {
  const int cells_x = cols_ - 1, cells_y = rows_ - 1;
  if (cells_x <= 0 || cells_y <= 0) return;
  half_diagonal_ = 0.5 * std::sqrt(2.0) * config_.resolution_m * (1.0 + 1e-9) +
                   1e-6 * std::max(1.0, config_.max_distance_m);
  cell_diagonal_ = 2.0 * half_diagonal_;
  slope_ = 1.0 + 2e-6 * std::max(1.0, config_.max_distance_m) / config_.resolution_m + 1e-9;
  const int size = 1 << kBlockShift;
  block_cols_ = (cells_x + size - 1) / size;
  const int block_rows = (cells_y + size - 1) / size;
  block_min_.assign(static_cast<size_t>(block_cols_) * block_rows, 0);
  for (int br = 0; br < block_rows; ++br) {
    for (int bc = 0; bc < block_cols_; ++bc) {
      // Nodes of every cell in the block, including the far edge.
      float low = values_[static_cast<size_t>(br * size) * cols_ + bc * size];
      for (int r = br * size; r <= std::min(rows_ - 1, (br + 1) * size); ++r) {
        for (int c = bc * size; c <= std::min(cols_ - 1, (bc + 1) * size); ++c)
          low = std::min(low, node(c, r));
      }
      // Round down, and make sure the lookup's own product never exceeds the node value.
      int units = static_cast<int>(std::min(255.0, std::floor(low / kBlockUnitM)));
      while (units > 0 && kBlockUnitM * units > low) --units;
      block_min_[static_cast<size_t>(br) * block_cols_ + bc] =
          static_cast<std::uint8_t>(std::max(0, units));
    }
  }
}

double DistanceGrid::distance(const Eigen::Vector2d& p_field, Eigen::Vector2d* gradient) const {
  if (values_.empty() || !p_field.allFinite()) {
    if (gradient) gradient->setZero();
    return config_.max_distance_m;
  }
  const Eigen::Vector2d g = (p_field - origin_) / config_.resolution_m;
  // Clamp into the grid; the part outside adds to the distance (a lower bound of the truth).
  const double gx = std::clamp(g.x(), 0.0, cols_ - 1.0);
  const double gy = std::clamp(g.y(), 0.0, rows_ - 1.0);
  const double ox = g.x() - gx, oy = g.y() - gy;
  const double outside =
      ox == 0.0 && oy == 0.0 ? 0.0 : config_.resolution_m * std::sqrt(ox * ox + oy * oy);
  const int c0 = std::min(static_cast<int>(gx), cols_ - 2);
  const int r0 = std::min(static_cast<int>(gy), rows_ - 2);
  const double fx = gx - c0, fy = gy - r0;
  const double v00 = node(c0, r0), v10 = node(c0 + 1, r0);
  const double v01 = node(c0, r0 + 1), v11 = node(c0 + 1, r0 + 1);
  const double top = v00 + fx * (v10 - v00), bottom = v01 + fx * (v11 - v01);
  if (gradient) {
    const double dx = (1.0 - fy) * (v10 - v00) + fy * (v11 - v01);
    const double dy = bottom - top;
    *gradient = Eigen::Vector2d(dx, dy) / config_.resolution_m;
  }
  return top + fy * (bottom - top) + outside;
}

}  // namespace houghloc
