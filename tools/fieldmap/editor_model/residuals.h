#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose2.h"

namespace houghloc::fieldmap {

struct ResidualConfig {
  /// Points farther than this from every map feature are counted as unmatched (robots, the
  /// ball, lines the map lacks) and left out of the statistics, m.
  double max_distance_m = 0.5;
};

/// Distances of the points assigned to one feature (each point to its nearest feature), m.
struct ResidualStats {
  int count = 0;
  double mean_m = 0.0;
  double p95_m = 0.0;
};

struct FeatureResidual {
  FeatureRef feature;
  ResidualStats stats;
};

struct ResidualReport {
  ResidualStats overall;
  std::vector<FeatureResidual> features;  ///< features with at least one point, map order
  int unmatched = 0;                      ///< points beyond max_distance_m
};

/// How well a frame's line points (robot frame) fit the map at `field_T_robot`: every point goes
/// to its nearest feature (nearestFeature), and the distances give mean and 95th percentile per
/// feature and overall. A map dimension that is wrong shows as a feature with a large residual.
ResidualReport computeResiduals(const FieldModel& field,
                                const std::vector<Eigen::Vector2d>& points_robot,
                                const Pose2& field_T_robot, const ResidualConfig& config = {});

}  // namespace houghloc::fieldmap
