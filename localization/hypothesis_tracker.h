#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/ground_points.h"
#include "localization/feature_index.h"
#include "localization/localization_hint.h"
#include "localization/tracked_hypotheses.h"
#include "localization/tracker_config.h"

namespace houghloc {

/// Same names as DESIGN §5.2 poses.csv `status`.
enum class TrackerStatus { kInitializing, kTracking, kAmbiguous, kLost };
const char* trackerStatusName(TrackerStatus status);

/// What the last frame did, for the status message and tests.
struct TrackerStats {
  int points_in = 0;    ///< finite points of the last frame
  int points_used = 0;  ///< associated by the best hypothesis
  double best_inlier_share = 0.0;
  double seconds_without_points = 0.0;
  bool odometry_jump = false;   ///< in the last prediction
  bool time_backwards = false;  ///< in the last prediction
};

/// Multi-hypothesis tracking (paper, last part; Appendix A "Tracking"): a bounded set of Gaussian
/// pose hypotheses, each an EKF on (x, y, theta), predicted with odometry and corrected with the
/// frame's ground points; hypotheses the observations do not confirm lose weight and are dropped.
/// Global hypotheses come in through injectHypotheses() when needsGlobalHypotheses() asks.
/// Deterministic; never prints; outputs are always finite.
class HypothesisTracker {
 public:
  explicit HypothesisTracker(const FieldModel& field, const TrackerConfig& config = {});
  /// Shares a prebuilt index (building one costs tens of ms; copies of a tracker are cheap).
  HypothesisTracker(std::shared_ptr<const FeatureIndex> index, const TrackerConfig& config);

  /// One frame: predict() then correct().
  void update(std::int64_t t_us, const std::optional<Pose2>& odometry, const GroundPoints& points);
  /// Moves every hypothesis by the odometry since the last frame (cumulative odometry, DESIGN §3;
  /// empty or non-finite = none this frame).
  void predict(std::int64_t t_us, const std::optional<Pose2>& odometry);
  /// Corrects every hypothesis with the points (iterated EKF), re-weights, merges and prunes.
  void correct(const GroundPoints& points);

  /// Adds global hypotheses (e.g. from the Hough localizer): weight = share x belief x likelihood
  /// (TrackerConfig::belief_floor; share injected_share or periodic_injected_share).
  void injectHypotheses(const std::vector<GaussianPose>& poses);
  /// DESIGN §7 hints: UNKNOWN, RESET_TO, ADD, OWN_HALF, MIRROR.
  void applyHint(const LocalizationHint& hint);
  /// The prior of a new pose (docs/tracking.md "How weights flow"): the current mixture at `pose`
  /// (peak-normalised, 0..1, at least belief_floor), the larger of the set's and the recent
  /// RESET_TO hint's (TrackerConfig::hint_prior_s); 1 when the set is empty.
  double belief(const GaussianPose& pose) const;

  /// True when global hypotheses would help now: none left, an odometry jump, the best hypothesis
  /// disagrees with the observations for several frames or explains suddenly less than it used
  /// to, its weight or certainty dropped, or the low-rate period has passed since the last
  /// injection.
  bool needsGlobalHypotheses() const;
  TrackerStatus status() const;
  /// True when a hypothesis near the best one's mirror has a comparable weight.
  bool topHypothesesMirrorAmbiguous() const;

  /// Best first, weights sum to one.
  const std::vector<TrackedHypothesis>& hypotheses() const { return hypotheses_; }
  const TrackerStats& lastStats() const { return stats_; }
  const TrackerConfig& config() const { return config_; }

 private:
  /// New hypotheses by the one weight rule; `share` is the set's share they may take at most.
  void addPoses(const std::vector<GaussianPose>& poses, double share);
  void markInjected();
  bool bestIsLost() const;
  /// The hypothesis' inlier share dropped suddenly (share_drop above the alarm): kidnap suspect.
  bool dropAlarm(const TrackedHypothesis& h) const;
  /// Nothing but the period would ask for global hypotheses now.
  bool onlyPeriodic() const;
  void finishSet();

  TrackerConfig config_;
  std::shared_ptr<const FeatureIndex> index_;
  OdometryInput odometry_;
  std::vector<TrackedHypothesis> hypotheses_;
  TrackerStats stats_;
  int next_id_ = 0;
  double seconds_since_injection_ = 0.0;
  bool jump_since_injection_ = false;
  bool blind_since_injection_ = false;  ///< no points for lost_without_points_s meanwhile
  /// The last RESET_TO hint's poses, moved by odometry (TrackerConfig::hint_prior_s), and their
  /// age.
  std::vector<GaussianPose> hint_prior_;
  double hint_prior_age_s_ = 0.0;
  bool global_after_hint_ = false;            ///< the hint is to be checked by a global run
  bool weight_drop_since_injection_ = false;  ///< TrackerConfig::best_weight_drop_ratio
};

}  // namespace houghloc
