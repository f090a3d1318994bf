#pragma once

#include <Eigen/Core>
#include <limits>

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

}  // namespace houghloc
