#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_models/field_model.h"

namespace houghloc {

struct DistanceGridConfig {
  double resolution_m = 0.02;   ///< cell size
  double margin_m = 0.5;        ///< extra area beyond the border strip covered by the grid
  double max_distance_m = 5.0;  ///< stored distances are clamped to this (saves nothing, bounds it)
};

/// Distance from the nearest line feature's centre line, precomputed on a regular grid over the
/// field plus border strip plus margin, for fast scoring (DESIGN §2). Lookups interpolate
/// bilinearly; outside the grid the distance to the grid's edge is added to the edge value.
class DistanceGrid {
 public:
  DistanceGrid() = default;
  DistanceGrid(const FieldModel& field, const DistanceGridConfig& config = {});

  /// Distance (m) from p_field to the nearest line, bilinear between exact values at the nodes.
  /// Inline: the hot path of every scoring loop (inside the grid: no clamping, no hypot).
  double distance(const Eigen::Vector2d& p_field) const {
    const double gx = (p_field.x() - origin_.x()) * inv_resolution_;
    const double gy = (p_field.y() - origin_.y()) * inv_resolution_;
    if (gx >= 0.0 && gy >= 0.0 && gx < cols_ - 1.0 && gy < rows_ - 1.0) {
      const int c0 = static_cast<int>(gx), r0 = static_cast<int>(gy);
      const double fx = gx - c0, fy = gy - r0;
      const float* row0 = &values_[static_cast<size_t>(r0) * cols_ + c0];
      const float* row1 = row0 + cols_;
      const double top = row0[0] + fx * (row0[1] - row0[0]);
      const double bottom = row1[0] + fx * (row1[1] - row1[0]);
      return top + fy * (bottom - top);
    }
    return distance(p_field, nullptr);
  }
  /// Same, and the gradient of the interpolated distance (unit-less, points away from lines).
  double distance(const Eigen::Vector2d& p_field, Eigen::Vector2d* gradient) const;

  double resolution() const { return config_.resolution_m; }
  int cols() const { return cols_; }
  int rows() const { return rows_; }
  Eigen::Vector2d origin() const { return origin_; }  ///< field position of node (0, 0)
  bool empty() const { return values_.empty(); }

 private:
  float node(int col, int row) const { return values_[static_cast<size_t>(row) * cols_ + col]; }

  DistanceGridConfig config_;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  double inv_resolution_ = 0.0;
  int cols_ = 0;
  int rows_ = 0;
  std::vector<float> values_;
};

}  // namespace houghloc
