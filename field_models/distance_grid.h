#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
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
    if (gx >= 0.0 && gy >= 0.0 && gx < last_col_ && gy < last_row_) {
      return interpolate(gx, gy, static_cast<int>(gx), static_cast<int>(gy));
    }
    return distance(p_field, nullptr);
  }
  /// Same, and the gradient of the interpolated distance (unit-less, points away from lines).
  double distance(const Eigen::Vector2d& p_field, Eigen::Vector2d* gradient) const;
  /// distance(p_field) when it is below `limit_m`; otherwise a lower bound of it that is at least
  /// `limit_m` (cheap: far from the lines only a small block map is read, not the grid). For
  /// robust kernels that are zero beyond `limit_m`: same result as distance(), bit for bit.
  double distanceBelow(const Eigen::Vector2d& p_field, double limit_m) const {
    const double gx = (p_field.x() - origin_.x()) * inv_resolution_;
    const double gy = (p_field.y() - origin_.y()) * inv_resolution_;
    if (gx >= 0.0 && gy >= 0.0 && gx < last_col_ && gy < last_row_) {
      const int c0 = static_cast<int>(gx), r0 = static_cast<int>(gy);
      const double bound =
          kBlockUnitM *
          block_min_[static_cast<size_t>(r0 >> kBlockShift) * block_cols_ + (c0 >> kBlockShift)];
      if (bound >= limit_m) return bound;
      return interpolate(gx, gy, c0, r0);
    }
    return distance(p_field, nullptr);
  }

  /// Hint: distanceBelow(p_field, limit_m) will be called soon. Starts loading the grid nodes
  /// it will read (only near lines), so that a batch of lookups waits for memory once.
  void prefetch(const Eigen::Vector2d& p_field, double limit_m) const {
    const double gx = (p_field.x() - origin_.x()) * inv_resolution_;
    const double gy = (p_field.y() - origin_.y()) * inv_resolution_;
    if (!(gx >= 0.0 && gy >= 0.0 && gx < last_col_ && gy < last_row_)) return;
    const int c0 = static_cast<int>(gx), r0 = static_cast<int>(gy);
    const double bound =
        kBlockUnitM *
        block_min_[static_cast<size_t>(r0 >> kBlockShift) * block_cols_ + (c0 >> kBlockShift)];
    if (bound >= limit_m) return;
    const float* row0 = &values_[static_cast<size_t>(r0) * cols_ + c0];
    __builtin_prefetch(row0);
    __builtin_prefetch(row0 + cols_);
  }
  /// A lower bound (m) of the exact distance from p_field to the nearest line (not of the
  /// interpolated one): the block's smallest node less half a cell diagonal; 0 off the grid.
  /// One read of the small block map, for skipping points that are certainly far from lines.
  double lowerBound(const Eigen::Vector2d& p_field) const {
    const double gx = (p_field.x() - origin_.x()) * inv_resolution_;
    const double gy = (p_field.y() - origin_.y()) * inv_resolution_;
    if (!(gx >= 0.0 && gy >= 0.0 && gx < last_col_ && gy < last_row_)) return 0.0;
    const int c0 = static_cast<int>(gx), r0 = static_cast<int>(gy);
    return kBlockUnitM * block_min_[static_cast<size_t>(r0 >> kBlockShift) * block_cols_ +
                                    (c0 >> kBlockShift)] -
           half_diagonal_;
  }

  /// True when p_field lies where lookups interpolate the grid (not beyond its edge).
  bool onGrid(const Eigen::Vector2d& p_field) const {
    const double gx = (p_field.x() - origin_.x()) * inv_resolution_;
    const double gy = (p_field.y() - origin_.y()) * inv_resolution_;
    return gx >= 0.0 && gy >= 0.0 && gx < last_col_ && gy < last_row_;
  }
  /// A lower bound of distance(q') for every q' = q + (dx, dy) with |dx| + |dy| <= moved_l1_m
  /// and length <= moved_m, where distanceBelow(q, limit) returned `seen_m`; where it is >=
  /// limit, so is distanceBelow(q', limit). Why it holds: on the grid `seen_m` is at most the
  /// interpolated distance D(q); each partial derivative of D is at most 1 (adjacent nodes differ
  /// by at most a cell), and D is within a cell diagonal of the exact (1-Lipschitz) distance.
  /// Beyond the grid's edge `seen_m` is D at the nearest grid point plus the distance to it; that
  /// distance shrinks by at most moved_m. Lets a scan skip positions where a point cannot come
  /// near a line.
  double movedLowerBound(const Eigen::Vector2d& q, double seen_m, double moved_l1_m,
                         double moved_m) const {
    return movedLowerBound(onGrid(q), seen_m, moved_l1_m, moved_m);
  }
  /// The same with q_on_grid = onGrid(q), for a caller that tries several moves from one q.
  double movedLowerBound(bool q_on_grid, double seen_m, double moved_l1_m, double moved_m) const {
    if (!q_on_grid) return seen_m - slope_ * moved_l1_m - moved_m;
    return std::max(seen_m - slope_ * moved_l1_m, seen_m - moved_m - 2.0 * cell_diagonal_);
  }
  /// The longest move that movedLowerBound keeps at or above `limit_m`, slightly shortened
  /// against rounding; negative when no move does. A move of t units has an L1 length of at most
  /// t * l1_per_unit + rounding_m and a length of at most t * length_per_unit + rounding_m (a
  /// scan's direction and the rounding of its positions). The bound falls as the move grows, so
  /// a scan skips every position up to this far at once instead of testing each.
  double farMove(bool q_on_grid, double seen_m, double limit_m, double l1_per_unit,
                 double length_per_unit, double rounding_m) const {
    const double excess = seen_m - limit_m;
    const double t =
        q_on_grid
            ? std::max((excess - slope_ * rounding_m) / (slope_ * l1_per_unit),
                       (excess - rounding_m - 2.0 * cell_diagonal_) / length_per_unit)
            : (excess - (slope_ + 1.0) * rounding_m) / (slope_ * l1_per_unit + length_per_unit);
    return t - 1e-9 * (1.0 + std::abs(t));
  }

  double resolution() const { return config_.resolution_m; }
  int cols() const { return cols_; }
  int rows() const { return rows_; }
  Eigen::Vector2d origin() const { return origin_; }  ///< field position of node (0, 0)
  bool empty() const { return values_.empty(); }

 private:
  /// Bilinear value at grid coordinates (gx, gy) strictly inside the grid; (c0, r0) its cell.
  double interpolate(double gx, double gy, int c0, int r0) const {
    const double fx = gx - c0, fy = gy - r0;
    const float* row0 = &values_[static_cast<size_t>(r0) * cols_ + c0];
    const float* row1 = row0 + cols_;
    const double top = row0[0] + fx * (row0[1] - row0[0]);
    const double bottom = row1[0] + fx * (row1[1] - row1[0]);
    return top + fy * (bottom - top);
  }
  float node(int col, int row) const { return values_[static_cast<size_t>(row) * cols_ + col]; }
  void buildBlockMinima();

  /// Cells per block side of block_min_ as a power of two (4 cells: 8 cm at 2 cm).
  static constexpr int kBlockShift = 2;
  static constexpr double kBlockUnitM = 0.01;  ///< unit of block_min_ (1 cm, up to 2.55 m)

  DistanceGridConfig config_;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  double inv_resolution_ = 0.0;
  int cols_ = 0;
  int rows_ = 0;
  /// cols_ - 1 and rows_ - 1: lookups interpolate where 0 <= gx < last_col_, 0 <= gy < last_row_.
  double last_col_ = -1.0;
  double last_row_ = -1.0;
  std::vector<float> values_;
  /// Per block of 2^kBlockShift x 2^kBlockShift cells: the smallest of its nodes (a lower bound
  /// of every bilinear lookup inside it, as a convex combination of nodes), rounded down to
  /// kBlockUnitM. A small map (MSL: 60 KB against 3.8 MB of nodes) that stays in cache, so
  /// scoring reads the grid only near lines (distanceBelow).
  int block_cols_ = 0;
  std::vector<std::uint8_t> block_min_;
  /// Half a cell diagonal plus the float rounding of a node: every point of a cell is this close
  /// to one of its nodes, and the distance is 1-Lipschitz (lowerBound).
  double half_diagonal_ = 0.0;
  /// A cell diagonal plus the float rounding of a node: |D - f| <= this (movedLowerBound).
  double cell_diagonal_ = 0.0;
  /// 1, enlarged by the float rounding of two nodes over a cell: bounds |dD/dx|, |dD/dy|.
  double slope_ = 0.0;
};

}  // namespace houghloc
