#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_models/ground_points.h"
#include "localization/feature_index.h"
#include "localization/gaussian_pose.h"

namespace houghloc {

/// Correction of one Gaussian pose by a frame's ground points (Appendix A, tracking): iterated
/// EKF = Gauss-Newton on prior + robust point-to-line cost, re-associating every iteration.
struct PointUpdateConfig {
  double point_sigma_m = 0.03;     ///< std of a ground point across its line, m
  double max_association_m = 0.5;  ///< points farther from every line are not associated, m
  double gate_chi2 = 9.0;          ///< Mahalanobis gate r^2 / (J P J^T + sigma^2), 1 dof
  /// Robust kernel. Cauchy (redescending) keeps far outliers from steering directions the lines
  /// leave unconstrained (e.g. heading when only the centre circle is seen); Huber is convex.
  enum class Kernel { kHuber, kCauchy };
  Kernel kernel = Kernel::kCauchy;
  /// Kernel scale in innovation standard deviations sqrt(J P J^T + sigma^2): wide while the pose
  /// is uncertain (large first steps), as tight as point_sigma_m once the iterations converge.
  double kernel_sigmas = 2.0;
  int max_iterations = 6;
  /// Iterations before the last one use an evenly strided subset of at most this many points.
  int max_iteration_points = 150;
  /// Fewer associated points than this share: one more (final) pass only, no polishing.
  double poor_association_share = 0.25;  ///< Gauss-Newton iterations per frame
  double converged_m = 1e-3;             ///< stop when a step moves less than this, m
  double converged_rad = 1e-3;           ///< and turns less than this, rad
  /// Points along one line have correlated errors (camera pose, line width); their information is
  /// scaled so that no more than this many count as independent. Keeps covariances honest.
  double max_effective_points = 40.0;
  int min_points = 5;                ///< fewer associated points: no correction
  double likelihood_sigma_m = 0.05;  ///< std of the per-point likelihood used for weights, m
  double outlier_chi2 = 9.0;         ///< per-point log-likelihood floor -0.5 * this (outliers)
  double inlier_m = 0.08;            ///< a point this close to a line is an inlier, m
  /// Start search along a wide prior (docs/tracking.md "Correction"). Gauss-Newton from the
  /// prior mean re-associates each point with its nearest line, so it converges only to a fit
  /// within about half a line spacing of the mean; a pose known only along a line (a global
  /// line hypothesis, a hint) would stay where it was put when a crossing line comes into view.
  /// When the prior's largest position std exceeds search_min_sigma_m, starts every
  /// search_step_m along that axis within search_sigmas std (heading moved with the prior's
  /// correlation) are scored by prior + capped point log-likelihood; the best one starts the
  /// iterations. search_max_starts <= 1 turns the search off.
  double search_min_sigma_m = 0.25;  ///< m; half the closest line spacing (goal area 0.5 m)
  double search_step_m = 0.1;        ///< m; well inside the ~0.25 m basin of one start
  double search_sigmas = 3.0;        ///< search half-width in prior std
  int search_max_starts = 61;        ///< at most this many starts (+-3 m at 0.1 m)
  /// The camera's recorded pitch and roll may be off by about this much (an IMU bias, a leaning
  /// body, a head joint that slipped; a 2 deg pitch error moves a point 2 m away by 0.3 m), rad,
  /// std; 0: the recorded angle is taken as exact. A frame the recorded pose explains poorly
  /// (mean per-point log-likelihood below -tilt_min_gain) is fitted again with the tilt as a
  /// nuisance of the pose (points carry GroundPoint::tilt_jacobian), and that fit is kept when
  /// it explains the points by tilt_min_gain better: a tilted camera then shifts no pose that
  /// odometry holds, and the hypothesis where the robot is keeps explaining the points. The
  /// tilt is the frame's own; one that stays is the CameraPoseCorrector's to remove.
  double pitch_sigma_rad = 0.035;  ///< 2 deg; docs/tracking.md "Camera tilt"
  double roll_sigma_rad = 0.0;
  double tilt_min_gain = 0.5;  ///< mean per-point log-likelihood
};

struct PointUpdateResult {
  GaussianPose posterior;     ///< weight copied from the prior
  int num_points = 0;         ///< finite points given
  int num_associated = 0;     ///< passed the gates in the last iteration
  int num_inliers = 0;        ///< within inlier_m of a line at the posterior
  double inlier_share = 0.0;  ///< num_inliers / num_points (0 without points)
  /// Mean per-point log-likelihood (truncated Gaussian), in [-outlier_chi2 / 2, 0].
  double mean_log_likelihood = 0.0;
  int iterations = 0;
  bool corrected = false;  ///< the posterior differs from the prior
  /// The frame's camera (roll, pitch) error fitted with the pose (PointUpdateConfig::
  /// pitch_sigma_rad, roll_sigma_rad), rad.
  Eigen::Vector2d tilt = Eigen::Vector2d::Zero();
};

PointUpdateResult updateWithGroundPoints(const GaussianPose& prior,
                                         const std::vector<GroundPoint>& points,
                                         const FeatureIndex& index,
                                         const PointUpdateConfig& config);

}  // namespace houghloc
