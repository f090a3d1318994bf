#pragma once

#include <cstdint>
#include <random>

#include "field_models/pose2.h"
#include "tools/render/scenario.h"

namespace houghloc {

/// Simulated walking odometry (DESIGN §3: a cumulative pose in the robot's own odometry frame).
/// Each step's true motion is scaled by the biases, grows random-walk noise (sigma of the
/// accumulated error after walking 1 m is translation_noise m), and during foot slips reports
/// the commanded motion although the robot moved only slip_factor of it.
class OdometryModel {
 public:
  OdometryModel(const OdometryConfig& config, std::uint32_t seed, double fps);

  /// Adds the true robot-frame motion since the previous frame; returns the cumulative pose.
  const Pose2& update(const Pose2& true_motion);
  const Pose2& pose() const { return pose_; }

 private:
  OdometryConfig config_;
  double frame_period_s_;
  std::mt19937 rng_;
  Pose2 pose_;
  double slip_left_s_ = 0.0;  ///< remaining time of the current slip
};

}  // namespace houghloc
