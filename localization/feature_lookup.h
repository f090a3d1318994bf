#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "field_models/field_model.h"

namespace houghloc {

/// Nearest line feature of a map, precomputed per cell, for the point-to-line residuals of the
/// Gauss-Newton refinement (paper step 4, "refine the survivors").
class FeatureLookup {
 public:
  /// Residual of one field point against its nearest feature: distance (m) and the unit direction
  /// from the feature to the point (d distance / d point). For a segment interior this is the
  /// point-to-line distance along the line normal.
  struct Residual {
    double distance_m = 0.0;
    Eigen::Vector2d direction = Eigen::Vector2d::Zero();
    bool valid = false;
  };

  FeatureLookup() = default;
  /// Cells of `resolution_m` over the carpet plus `margin_m`.
  FeatureLookup(const FieldModel& field, double resolution_m, double margin_m);

  /// Hint: residual(p) will be called soon; starts loading its cell.
  void prefetch(const Eigen::Vector2d& p) const {
    if (cells_.empty() || !p.allFinite()) return;
    const int c =
        std::clamp(static_cast<int>((p.x() - origin_.x()) * inv_resolution_), 0, cols_ - 1);
    const int r =
        std::clamp(static_cast<int>((p.y() - origin_.y()) * inv_resolution_), 0, rows_ - 1);
    __builtin_prefetch(&cells_[static_cast<std::size_t>(r) * cols_ + c]);
  }
  /// distance_m is signed for segment interiors and arcs (side of the line), >= 0 otherwise.
  /// Inline for the common case, a point beside a segment's interior (the refinement's hot path).
  Residual residual(const Eigen::Vector2d& p) const {
    if (cells_.empty() || !p.allFinite()) return {};
    const int c =
        std::clamp(static_cast<int>((p.x() - origin_.x()) * inv_resolution_), 0, cols_ - 1);
    const int r =
        std::clamp(static_cast<int>((p.y() - origin_.y()) * inv_resolution_), 0, rows_ - 1);
    const int code = cells_[static_cast<std::size_t>(r) * cols_ + c];
    if (code < 0) return {};
    if ((code & 3) == static_cast<int>(FeatureKind::kSegment)) {
      // Signed point-to-line distance inside the segment: smooth across the line for Gauss-Newton.
      const Line& line = lines_[code >> 2];
      const double t = (p - line.a).dot(line.u);
      if (t > 0.0 && t < line.length) {
        Residual out;
        out.direction = Eigen::Vector2d(-line.u.y(), line.u.x());
        out.distance_m = out.direction.dot(p - line.a);
        out.valid = true;
        return out;
      }
    }
    return residualBeyond(p, code);
  }

 private:
  /// residual() where the fast path does not apply: a segment's end, an arc or a mark (`code`
  /// is the cell's entry).
  Residual residualBeyond(const Eigen::Vector2d& p, int code) const;

  struct Line {
    Eigen::Vector2d a, u;  ///< start and unit direction
    double length;
  };
  FieldModel field_copy_;
  std::vector<Line> lines_;  ///< per segment, precomputed
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  double resolution_ = 0.05;
  double inv_resolution_ = 20.0;
  int cols_ = 0, rows_ = 0;
  /// Per cell: index * 4 + kind of the nearest feature, -1 for none (2 bytes, not 8: the table
  /// of a large map stays in cache).
  std::vector<std::int16_t> cells_;
};

}  // namespace houghloc
