#pragma once

#include <limits>
#include <vector>

#include "field_models/distance_grid.h"
#include "field_models/pose2.h"
#include "localization/hough_transform.h"
#include "localization/pose_hypothesis.h"

namespace houghloc {

struct ScoringConfig {
  double kernel_width_m = 0.15;     ///< robust kernel k(d) = max(0, 1 - (d / width)^2)
  double inlier_distance_m = 0.08;  ///< a point within this of a line counts as an inlier
};

struct PoseScore {
  double score = 0.0;         ///< sum_i w_i k(d_i), point weight
  double inlier_share = 0.0;  ///< share of the point weight with d_i <= inlier_distance_m
};

/// Scores field_T_robot against the whole map: distances of the transformed points to the
/// nearest line (distance grid, so segments with their extents, arcs and marks) through a robust
/// kernel (Appendix A step 4). Shared with the exhaustive baseline.
PoseScore scorePose(const WeightedPoints& points, const Pose2& field_T_robot,
                    const DistanceGrid& grid, const ScoringConfig& config);

/// scorePose(points, Pose2(t.x(), t.y(), theta_rad), grid, config) for every translation t (a
/// scan along lines at one heading): the same numbers, bit for bit, with the points rotated
/// once instead of once per pose.
std::vector<PoseScore> scoreTranslations(const WeightedPoints& points, double theta_rad,
                                         const std::vector<Eigen::Vector2d>& translations,
                                         const DistanceGrid& grid, const ScoringConfig& config);

/// scorePose(points, Pose2(t.x(), t.y(), theta_rad), grid, config).score at t = t0 + s u for
/// every s of `s_values` (increasing; u a unit vector): the scan along parallel lines. The same
/// numbers, bit for bit (each sum adds the same terms in the same order; a point adds exactly
/// zero where it is beyond the kernel), but point by point: from where a point is far from every
/// line it skips the positions at which the grid's bound says it cannot come near one.
/// reach: when no position can score `reach` or more, the scan may stop early and return an
/// empty vector (a point adds at most its weight, so after each point the best sum so far plus
/// the weight still to come bounds every position's score).
std::vector<double> scoreAlongLine(const WeightedPoints& points, double theta_rad,
                                   const Eigen::Vector2d& t0, const Eigen::Vector2d& u,
                                   const std::vector<double>& s_values, const DistanceGrid& grid,
                                   const ScoringConfig& config,
                                   double reach = -std::numeric_limits<double>::infinity());

struct PruningConfig {
  double min_inlier_share = 0.25;     ///< drop candidates with fewer points on map segments
  double min_relative_score = 0.5;    ///< ... or scoring below this share of the best candidate
  int keep = 20;                      ///< at most this many survivors, best first
  double duplicate_distance_m = 0.2;  ///< survivors closer than this ...
  double duplicate_angle_rad = 0.08;  ///< ... and this in heading count once
};

/// Step 4 pruning with segment extents: a pose built from infinite lines whose points fall on a
/// line's extension (off the segment) scores low against the distance grid; keeps the best
/// `keep` distinct candidates that pass both thresholds, sorted by score. Uses each candidate's
/// `score` and `inlier_share`.
std::vector<PoseHypothesis> pruneCandidates(std::vector<PoseHypothesis> candidates,
                                            const PruningConfig& config);

/// At most max_points points picked at an even stride, weights scaled to keep the total weight
/// (deterministic; for cheap pre-scoring and for capping huge inputs).
WeightedPoints subsamplePoints(const WeightedPoints& points, std::size_t max_points);

}  // namespace houghloc
