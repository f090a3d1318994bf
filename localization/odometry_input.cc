#include "localization/odometry_input.h"

#include <algorithm>
#include <cmath>

namespace houghloc {

MotionStep OdometryInput::step(std::int64_t t_us, const std::optional<Pose2>& odometry) {
  MotionStep out;
  if (has_time_) {
    const double dt = 1e-6 * static_cast<double>(t_us - last_t_us_);
    out.time_backwards = dt < 0.0;
    out.dt_s = std::clamp(dt, 0.0, config_.max_dt_s);
  }
  // Time going backwards resynchronises the clock: later frames step from this one.
  has_time_ = true;
  last_t_us_ = t_us;

  const bool valid = odometry.has_value() && odometry->isFinite();
  if (!valid) {
    // Within the timeout the next valid reading will carry the motion; after it, nobody knows.
    const double since = 1e-6 * static_cast<double>(t_us - last_odometry_t_us_);
    if (!has_odometry_) {
      out.unknown_s = out.dt_s;
    } else if (since > config_.timeout_s) {
      // The frame that crosses the timeout inflates for the whole time since the last reading:
      // the next reading will only re-anchor, so nothing else accounts for it.
      out.unknown_s =
          since - out.dt_s <= config_.timeout_s ? std::min(since, config_.max_dt_s) : out.dt_s;
    }
    return out;
  }
  if (!has_odometry_) {
    has_odometry_ = true;
    last_odometry_ = *odometry;
    last_odometry_t_us_ = t_us;
    return out;  // the first reading only anchors the odometry frame
  }
  const Pose2 motion = last_odometry_.inverse() * *odometry;
  const double dt_odom =
      std::clamp(1e-6 * static_cast<double>(t_us - last_odometry_t_us_), 0.0, config_.max_dt_s);
  const double max_trans = config_.max_speed_m_per_s * dt_odom + config_.jump_slack_m;
  const double max_rot = config_.max_turn_rad_per_s * dt_odom + config_.jump_slack_rad;
  last_odometry_ = *odometry;
  last_odometry_t_us_ = t_us;
  const bool implausible = !motion.isFinite() || std::hypot(motion.x, motion.y) > max_trans ||
                           std::abs(motion.theta) > max_rot;
  if (implausible) {
    // A reset of the odometry source or a glitch: the true motion is unknown, not huge.
    out.jump = true;
    out.unknown_s = std::max(dt_odom, out.dt_s);
    return out;
  }
  if (dt_odom > config_.timeout_s) {
    // The frames since the timeout were already inflated as unknown motion; the reading after
    // such a gap (say a fall, whose odometry is garbage) only re-anchors the odometry frame.
    out.unknown_s = out.dt_s;
    return out;
  }
  out.motion = motion;
  out.has_motion = true;
  return out;
}

}  // namespace houghloc
