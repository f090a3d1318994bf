#pragma once

#include <vector>

#include "localization/gaussian_pose.h"

namespace houghloc {

/// One tracked hypothesis: a Gaussian pose (its weight normalised over the set) and its history.
struct TrackedHypothesis {
  GaussianPose pose;
  int id = 0;                  ///< stable while the hypothesis lives
  int age_frames = 0;          ///< frames since it was created
  double inlier_share = 0.0;   ///< of the last frame with points
  int points_associated = 0;   ///< points that passed the gates in the last frame
  int disagreeing_frames = 0;  ///< consecutive frames with too few inliers
  /// Running mean of the inlier share over the frames judged so far (what this hypothesis
  /// usually explains here: a view with robots or a busy background explains less); negative
  /// until the first judged frame.
  double expected_inlier_share = -1.0;
  /// CUSUM of the inlier share's drop below expected_inlier_share (share x frames): a kidnap
  /// shows as a sudden drop even when the old pose still explains half of the new view.
  double share_drop = 0.0;
};

/// Merging and pruning of the tracked set.
struct TrackedSetConfig {
  int max_hypotheses = 12;         ///< the weakest beyond this are dropped
  double merge_chi2 = 4.0;         ///< merge when dmu^T (Pa + Pb)^-1 dmu is below this
  double merge_distance_m = 0.05;  ///< or when closer than this in position, m
  double merge_angle_rad = 0.05;   ///< and in heading, rad
  /// Never merge farther apart than this (a wide Gaussian would swallow a sharp one), m / rad.
  double merge_max_distance_m = 0.3;
  double merge_max_angle_rad = 0.3;
  double prune_relative_weight = 1e-3;  ///< drop hypotheses weaker than this times the best
};

/// Moment-matched Gaussian of two (weights add); angles are averaged around a's heading.
GaussianPose mergeGaussians(const GaussianPose& a, const GaussianPose& b);

/// Squared Mahalanobis distance of two means under the sum of their covariances.
double mahalanobisSquared(const GaussianPose& a, const GaussianPose& b);

/// Scales weights to sum to one (equal weights when they are all zero or not finite).
void normalizeTrackedWeights(std::vector<TrackedHypothesis>* set);

/// Sorts best first; ties broken by id so the order is deterministic.
void sortByWeight(std::vector<TrackedHypothesis>* set);

/// Merges every pair that has converged to the same pose; the stronger keeps its id.
void mergeConverged(const TrackedSetConfig& config, std::vector<TrackedHypothesis>* set);

/// Drops weak hypotheses (except newcomers, age 0, not yet judged by points) and those beyond
/// max_hypotheses, then normalises and sorts.
void pruneWeak(const TrackedSetConfig& config, std::vector<TrackedHypothesis>* set);

/// True when b is within the tolerances of a's mirror (-x, -y, theta + pi).
bool areMirrors(const Pose2& a, const Pose2& b, double tolerance_m, double tolerance_rad);

/// Summed weight of the poses within the tolerances of the first (best) one's mirror twin: how
/// close an estimate is to flipping (poses.csv `twin_weight`); 0 for an empty list.
double mirrorTwinWeight(const std::vector<GaussianPose>& best_first, double tolerance_m,
                        double tolerance_rad);

}  // namespace houghloc
