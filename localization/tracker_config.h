#pragma once

#include "localization/feature_index.h"
#include "localization/motion_model.h"
#include "localization/odometry_input.h"
#include "localization/point_update.h"
#include "localization/tracked_hypotheses.h"

namespace houghloc {

/// Every tunable of the HypothesisTracker (config file section `tracker:`; see docs/tracking.md).
struct TrackerConfig {
  MotionModelConfig motion;
  OdometryInputConfig odometry;
  PointUpdateConfig update;
  TrackedSetConfig set;
  FeatureIndexConfig index;

  /// Frame likelihood = exp(likelihood_points * mean per-point log-likelihood): the frame counts
  /// as this many independent points when hypotheses are compared. Lower = slower decisions.
  double likelihood_points = 8.0;
  /// Differences of the mean per-point log-likelihood below this are ignored when hypotheses are
  /// compared (outliers near lines favour places with many lines by a few hundredths).
  double likelihood_deadband = 0.1;
  /// Weight share of the set given to newly injected global hypotheses (the rest stays), before
  /// the belief factor (belief_floor below).
  double injected_share = 0.2;
  /// Same for the low-rate injections while the best hypothesis agrees with the observations.
  double periodic_injected_share = 0.02;
  /// Weight share given to poses added by an ADD hint.
  double hint_add_share = 0.5;

  // When to ask for global hypotheses (needsGlobalHypotheses()).
  int min_points_to_judge = 20;        ///< frames with fewer points do not count as evidence
  double disagree_inlier_share = 0.5;  ///< a hypothesis explaining fewer points disagrees
  int disagree_frames = 5;             ///< that many frames in a row: LOST, ask for global
  /// Kidnap detector (a CUSUM): each judged frame adds expected - inlier share -
  /// share_drop_slack to the hypothesis' share_drop (not below 0); above share_drop_alarm
  /// (share x frames) the tracker asks for global hypotheses at once. One frame explaining
  /// nothing where everything used to be explained fires; 30 % less fires within four frames.
  /// The newcomers get periodic_injected_share: one that explains clearly more wins through the
  /// likelihood within a frame or two, and a false alarm (a robot walking into view) costs no
  /// more than a periodic injection. The expected share follows the inlier share at
  /// expected_share_rate per judged frame, so a lasting change stops the alarms.
  double share_drop_slack = 0.1;
  double share_drop_alarm = 0.6;
  double expected_share_rate = 0.05;  ///< per judged frame, 0..1
  /// The best hypothesis keeping less than this share of its weight through one frame's
  /// evidence (others explain the view clearly better) asks for global hypotheses at once, with
  /// injected_share: the held hypotheses may all be wrong (a wrong local fit losing to a wrong
  /// place while the true pose is not held); newcomers far from the belief get its floor, so a
  /// false alarm costs little. 0..1.
  double best_weight_drop_ratio = 0.5;
  double low_best_weight = 0.25;   ///< best normalised weight below this: ask
  double lost_sigma_m = 0.5;       ///< best position std above this: LOST, ask
  double periodic_global_s = 3.0;  ///< otherwise ask at this period, s
  /// No points for longer than this: the estimate is dead reckoning only, status LOST; the first
  /// frame with points again asks for global hypotheses, s.
  double lost_without_points_s = 5.0;

  // Symmetry and hints.
  double mirror_tolerance_m = 0.3;      ///< a hypothesis this close to another's mirror, m
  double mirror_tolerance_rad = 0.3;    ///< and in heading, rad
  double ambiguous_weight_ratio = 0.5;  ///< mirror weight >= this * best weight: AMBIGUOUS
  double own_half_margin_m = 0.5;       ///< OWN_HALF mirrors hypotheses with x > this, m

  // The one weight rule for new hypotheses (global runs, kidnap alarms, after a fall, ADD hints;
  // docs/tracking.md "How weights flow"): weight = share x belief(pose) x own likelihood, where
  // belief = max(belief_floor, sum_j w_j exp(-chi2_j / 2)) is the current mixture at the pose
  // (peak-normalised, covariances of both plus the spread below added) and 1 without hypotheses.
  /// Belief of a pose far from every hypothesis (relative to the best place): what a kidnap or a
  /// wrong start costs. A mirror twin of a well-localized track starts here and, fed only by
  /// injections that re-find it, cannot rise above it while the likelihood cannot tell them
  /// apart. 0..1.
  double belief_floor = 0.02;
  /// Added to the covariances when the belief is evaluated (a placement by hand is decimetres
  /// off whatever sigma it claims), m and rad (std).
  double belief_spread_m = 0.5;
  double belief_spread_rad = 0.5;
  /// The poses of a RESET_TO hint, moved by odometry but never corrected by points, stay part of
  /// the belief for this long (belief = the larger of the set's and the hint's mixture), s. The
  /// hint is also checked against a global run on the next frame. Why: a hint decimetres off
  /// can be pulled onto a wrong local fit within a frame, with a covariance of millimetres; the
  /// belief must still say where the hint put the robot, or the true pose found later starts
  /// barely above its mirror twin.
  double hint_prior_s = 3.0;
};

}  // namespace houghloc
