#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "field_models/field_model.h"

namespace houghloc {

/// The line feature nearest to a point, and how far it is (centre line, m).
struct NearestFeature {
  FeatureRef feature;
  double distance_m = std::numeric_limits<double>::infinity();
  Eigen::Vector2d closest_point = Eigen::Vector2d::Zero();  ///< on the feature, field frame
};

/// Exact nearest line feature (segments, arcs and marks) to p_field; feature.index is -1 for a map
/// without features. O(number of features).
NearestFeature nearestFeature(const FieldModel& field, const Eigen::Vector2d& p_field);

/// Closest point of a mark (cross bars or dot disc) to p.
Eigen::Vector2d closestPointOnMark(const Mark& mark, const Eigen::Vector2d& p);

/// nearestFeature() for many points in a row, as the precomputed maps query it (every node of a
/// grid): the same result bit for bit (the feature, its distance and closest point; on a tie the
/// first feature in the map's order), several times faster. A feature is skipped when a cheap
/// lower bound of its distance (its bounding box; the full circle of an arc) already exceeds the
/// best distance found, and the search starts at the previous point's nearest feature, which on
/// a grid is usually the nearest again. Reads `field`, which must outlive the search.
class NearestFeatureSearch {
 public:
  explicit NearestFeatureSearch(const FieldModel& field);

  NearestFeature nearest(const Eigen::Vector2d& p_field);

 private:
  struct Bound {
    Eigen::Vector2d low, high;  ///< bounding box of a segment or mark
    double radius = -1.0;       ///< an arc's radius (box unused); < 0 for boxes
  };
  double lowerBound(const Bound& bound, const Eigen::Vector2d& p) const;

  const FieldModel& field_;
  std::vector<FeatureRef> features_;  ///< segments, arcs, marks: nearestFeature()'s order
  std::vector<Bound> bounds_;
  std::size_t last_ = 0;  ///< the previous point's nearest, the first one tried
};

}  // namespace houghloc
