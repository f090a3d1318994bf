#pragma once

#include <Eigen/Core>
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

  /// distance_m is signed for segment interiors and arcs (side of the line), >= 0 otherwise.
  Residual residual(const Eigen::Vector2d& p_field) const;

 private:
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
