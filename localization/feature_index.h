#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "field_models/field_model.h"

namespace houghloc {

struct FeatureIndexConfig {
  double resolution_m = 0.05;  ///< cell size of the candidate grid
  double margin_m = 1.0;       ///< area covered beyond the border strip, m
};

/// A map feature reduced to a primitive association can evaluate quickly: a segment (also each
/// bar of a cross mark), an arc, or a disc (a dot mark).
struct LinePrimitive {
  enum class Kind : std::uint8_t { kSegment, kArc, kDisc };
  Kind kind = Kind::kSegment;
  FeatureRef feature;                                    ///< the FieldModel feature this comes from
  Eigen::Vector2d a = Eigen::Vector2d::Zero();           ///< segment start, arc or disc centre
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  ///< segment unit direction
  double length = 0.0;                                   ///< segment length, arc or disc radius, m
  double start_rad = 0.0, sweep_rad = 0.0;               ///< arcs
  bool full_circle = false;
};

/// Where a field point meets its nearest feature. The residual is linear in the point along
/// `normal` near the match: residual = normal . (p - closest), so the Jacobian of a point-to-line
/// (point-to-circle, point-to-point) distance is normal^T dp/dpose.
struct Association {
  int primitive = -1;
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();  ///< unit, or zero inside a dot (no info)
  double residual_m = 0.0;                           ///< signed distance along normal
  double distance_m = 0.0;                           ///< |residual_m|
};

/// Evaluates one primitive exactly.
Association associateWith(const LinePrimitive& primitive, const Eigen::Vector2d& p_field);

/// The nearest line feature in O(1): each grid cell stores every primitive that can be nearest to
/// some point of the cell (those within the cell centre's nearest distance plus one cell
/// diagonal), so association evaluates a few candidates exactly instead of the whole map. The
/// lists have no length cap, so the answer is exact (and the same on every compiler) also where
/// many features meet, e.g. at a penalty cross near a line.
class FeatureIndex {
 public:
  FeatureIndex() = default;
  explicit FeatureIndex(const FieldModel& field, const FeatureIndexConfig& config = {});

  /// Nearest primitive to p_field; false outside the grid or for a map without features.
  bool associate(const Eigen::Vector2d& p_field, Association* out) const;

  const std::vector<LinePrimitive>& primitives() const { return primitives_; }
  bool empty() const { return primitives_.empty(); }

 private:
  FeatureIndexConfig config_;
  std::vector<LinePrimitive> primitives_;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();  ///< field position of cell (0, 0)'s corner
  double inv_resolution_ = 0.0;
  int cols_ = 0, rows_ = 0;
  /// Candidates of cell i: candidates_[cell_begin_[i] .. cell_begin_[i + 1]), nearest first.
  std::vector<std::uint32_t> cell_begin_;
  std::vector<std::int16_t> candidates_;
};

}  // namespace houghloc
