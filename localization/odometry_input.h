#pragma once

#include <cstdint>
#include <optional>

#include "field_models/pose2.h"

namespace houghloc {

/// When odometry is believed (DESIGN §3: cumulative pose, motion = inverse(prev) * curr).
struct OdometryInputConfig {
  double max_speed_m_per_s = 1.0;   ///< faster apparent motion is a jump (treated as unknown)
  double max_turn_rad_per_s = 5.0;  ///< faster apparent turning is a jump
  double jump_slack_m = 0.05;       ///< allowed on top of max speed * dt, m
  double jump_slack_rad = 0.2;      ///< allowed on top of max turn * dt, rad
  /// Without valid odometry for longer, the motion counts as unknown (and the next reading only
  /// re-anchors). Shorter gaps are bridged by the next reading, but the frames in between are
  /// corrected at the old pose with the old covariance, so keep it to a few frames.
  double timeout_s = 0.15;
  double max_dt_s = 60.0;  ///< longer gaps (clock glitches) are treated as this long, s
};

/// What happened between the previous frame and this one.
struct MotionStep {
  Pose2 motion;             ///< robot-frame motion from odometry (identity when none)
  bool has_motion = false;  ///< motion is valid and should be applied
  double dt_s = 0.0;        ///< frame time step, >= 0
  double unknown_s = 0.0;   ///< seconds of motion nobody measured: inflate for this long
  bool jump = false;        ///< odometry jumped implausibly (or reset)
  bool time_backwards = false;
};

/// Turns a stream of (time, optional cumulative odometry) into per-frame motions. Missing or
/// non-finite readings are skipped: the next valid reading composes the whole motion since the
/// last valid one, so a dropped message loses nothing.
class OdometryInput {
 public:
  explicit OdometryInput(const OdometryInputConfig& config = {}) : config_(config) {}

  MotionStep step(std::int64_t t_us, const std::optional<Pose2>& odometry);
  void reset() { *this = OdometryInput(config_); }

 private:
  OdometryInputConfig config_;
  bool has_time_ = false;
  std::int64_t last_t_us_ = 0;
  bool has_odometry_ = false;
  Pose2 last_odometry_;
  std::int64_t last_odometry_t_us_ = 0;
};

}  // namespace houghloc
