#pragma once

#include <Eigen/Core>

#include "field_models/pose2.h"
#include "localization/feature_lookup.h"
#include "localization/hough_transform.h"
#include "localization/map_signature.h"

namespace houghloc {

struct RefinementConfig {
  int iterations = 10;             ///< Gauss-Newton iterations at most
  double max_distance_m = 0.25;    ///< points farther than this from their line are ignored
  double huber_m = 0.03;           ///< Huber kernel width on the point-to-line distance
  double sigma_floor_m = 0.01;     ///< lower bound of the residual std dev in the covariance
  double effective_points = 30.0;  ///< neighbouring points are correlated: the information is
                                   ///< scaled as if at most this many points were independent
  double prior_sigma_m = 5.0;      ///< weak prior keeping unobservable directions finite
  double prior_sigma_rad = 1.0;    ///< same for the heading
  double converged_m = 1e-4;       ///< stop when the update is smaller (m, and rad times 1 m)
};

struct RefinementResult {
  Pose2 field_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();  ///< J^T W J (point weight / m^2)
  double rms_m = 0.0;                                     ///< weighted RMS distance of the inliers
  double inlier_weight = 0.0;
};

/// Gauss-Newton on point-to-line distances (Appendix A step 4, "refine the survivors" for
/// accuracy below the bin size): each point is paired with the nearest map feature at the
/// current pose, residuals are signed distances to the line (radial for arcs), Huber-weighted.
/// `frozen_direction` (unit, field frame; zero for none) keeps the position fixed along it, for
/// the paper's parallel-only case where the lines do not constrain it.
RefinementResult refinePose(const WeightedPoints& points, const Pose2& initial,
                            const FeatureLookup& features, const RefinementConfig& config,
                            const Eigen::Vector2d& frozen_direction = Eigen::Vector2d::Zero());

/// Same result, bit for bit, faster: points that the map's distance grid puts certainly farther
/// than max_distance_m from every line are skipped without a feature lookup.
RefinementResult refinePose(const WeightedPoints& points, const Pose2& initial,
                            const MapSignature& map, const RefinementConfig& config,
                            const Eigen::Vector2d& frozen_direction = Eigen::Vector2d::Zero());

/// The pose of refinePose(.., map, ..) alone: without the final pass over the points that
/// only computes information, covariance and rms (for coarse stages that keep only the pose).
Pose2 refinePoseMean(const WeightedPoints& points, const Pose2& initial, const MapSignature& map,
                     const RefinementConfig& config,
                     const Eigen::Vector2d& frozen_direction = Eigen::Vector2d::Zero());

}  // namespace houghloc
