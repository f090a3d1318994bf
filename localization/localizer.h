#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/ground_points.h"
#include "field_models/pose3.h"
#include "localization/global_hough_config.h"
#include "localization/hypothesis_tracker.h"
#include "localization/localization_hint.h"
#include "localization/tracker_config.h"

namespace houghloc {

class GlobalHoughLocalizer;

/// Everything the Localizer facade can be tuned with: config file sections `global:`,
/// `tracker:` and `localizer:` (DESIGN §2).
struct LocalizerConfig {
  GlobalHoughConfig global;
  TrackerConfig tracker;
  /// Global hypotheses handed to the tracker per injection (the best ones of locate()); on a
  /// point-symmetric map the missing twin of each is added (both fit the frame equally well).
  int max_injected_hypotheses = 8;
  /// A camera lower than this above the ground, rolled more than fallen_tilt_rad or pitched
  /// up more than that means the robot lies on the ground: odometry and points are not used.
  double fallen_camera_height_m = 0.2;
  double fallen_tilt_rad = 1.0;
  /// After getting up the global localizer runs on this many frames that give hypotheses: the
  /// first views of a robot that just stood up are often local (one corner, parallel lines), so
  /// a wrong pose can fit them until the head turns.
  int global_frames_after_fall = 30;
};

/// Status of an estimate (DESIGN §5.2 poses.csv, §7 pose_hypotheses_t).
using LocalizationStatus = TrackerStatus;  // INITIALIZING, TRACKING, AMBIGUOUS, LOST

/// One hypothesis of an estimate: a Gaussian pose (weight normalised over the set), with a stable
/// id and its age in frames (DESIGN §7 pose_hypothesis_t).
struct EstimateHypothesis {
  GaussianPose pose;
  int id = 0;
  int age_frames = 0;
};

/// What Localizer::process() returns for one frame.
struct LocalizationEstimate {
  std::int64_t t_us = 0;
  LocalizationStatus status = TrackerStatus::kInitializing;
  std::vector<EstimateHypothesis> hypotheses;  ///< best first, weights sum to one; may be empty
  /// The best hypothesis' pose; none while there is no hypothesis.
  std::optional<GaussianPose> best() const {
    if (hypotheses.empty()) return std::nullopt;
    return hypotheses.front().pose;
  }
  /// Summed weight of the hypotheses at the best one's mirror twin (-x, -y, theta + pi, within
  /// the tracker's mirror tolerances): how close the estimate is to flipping; 0 without any.
  double twin_weight = 0.0;
  // Diagnostics for the status message (DESIGN §7 localizer_status_t) and the timing summary.
  int points_in = 0;
  int points_used = 0;
  bool global_ran = false;  ///< the global localizer ran this frame
  bool fallen = false;      ///< the camera poses say the robot is lying on the ground
  double global_ms = 0.0;   ///< wall time of the global localizer this frame
  double tracker_ms = 0.0;  ///< wall time of prediction and correction
};

/// The one entry point of localization (DESIGN §2): odometry, camera poses and a frame's ground
/// points in, pose hypotheses out. Inside: a HypothesisTracker (EKF per hypothesis, paper's last
/// part) fed with GlobalHoughLocalizer hypotheses when it asks for them. Deterministic for the
/// same input; never prints; outputs are always finite. Not thread-safe (one caller at a time);
/// copies share the immutable map data.
class Localizer {
 public:
  /// Builds the map data once (tens of ms). Throws std::invalid_argument for an empty field.
  explicit Localizer(const FieldModel& field, const LocalizerConfig& config = {});
  ~Localizer();
  Localizer(const Localizer&);
  Localizer& operator=(const Localizer&);

  /// One frame. `odometry`: cumulative odometry pose (DESIGN §3), none or non-finite when
  /// unavailable. `robot_T_cameras`: the poses of the cameras that saw `points` (used to detect
  /// a fallen robot; may be empty). Times may repeat or go backwards (the frame is then treated
  /// as having no motion information).
  LocalizationEstimate process(std::int64_t t_us, const std::optional<Pose2>& odometry,
                               const std::vector<Pose3>& robot_T_cameras,
                               const GroundPoints& points);

  /// DESIGN §7 hints (UNKNOWN, RESET_TO, ADD, OWN_HALF, MIRROR); takes effect immediately and
  /// is reflected in the next estimate.
  void applyHint(const LocalizationHint& hint);

  /// The current estimate without a new frame (after applyHint, before the first frame).
  /// While the camera poses say the robot is fallen, the status is LOST (INITIALIZING without
  /// hypotheses); after it gets up, global hypotheses are injected as soon as lines are seen.
  LocalizationEstimate estimate() const;

  const LocalizerConfig& config() const { return config_; }
  const FieldModel& field() const { return *field_; }

 private:
  LocalizerConfig config_;
  std::shared_ptr<const FieldModel> field_;
  std::shared_ptr<const GlobalHoughLocalizer> global_;
  HypothesisTracker tracker_;
  bool point_symmetric_ = false;  ///< every map feature has a twin at (-x, -y)
  std::int64_t last_t_us_ = 0;
  bool fallen_ = false;
  /// Frames on which the global localizer runs even if the tracker does not ask (after a fall).
  int global_frames_pending_ = 0;
};

}  // namespace houghloc
