#include "tools/render/odometry_model.h"

#include <algorithm>
#include <cmath>

namespace houghloc {

OdometryModel::OdometryModel(const OdometryConfig& config, std::uint32_t seed, double fps)
    : config_(config), frame_period_s_(1.0 / fps) {
  std::seed_seq seq{seed, 2u, 0x0d0du};
  rng_.seed(seq);
}

const Pose2& OdometryModel::update(const Pose2& motion) {
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  // Draw every random number every frame, so the sequence does not depend on the motion.
  const double n_x = normal(rng_), n_y = normal(rng_), n_t = normal(rng_), n_tm = normal(rng_);
  const bool slip_starts = uniform(rng_) < config_.slip_rate_hz * frame_period_s_;
  if (slip_left_s_ <= 0.0 && slip_starts) slip_left_s_ = config_.slip_duration_s;
  const double dist = std::hypot(motion.x, motion.y);
  const double turn = std::abs(motion.theta);
  double scale = 1.0 + config_.scale_bias;
  double rot_scale = 1.0 + config_.rotation_bias;
  if (slip_left_s_ > 0.0) {
    // The legs did the commanded motion; the robot only moved slip_factor of it.
    const double commanded = 1.0 / std::max(0.2, config_.slip_factor);
    scale *= commanded;
    rot_scale *= commanded;
    slip_left_s_ -= frame_period_s_;
  }
  // Random-walk noise: variance grows linearly with the distance walked and the angle turned.
  const double sigma_xy = config_.translation_noise * std::sqrt(dist);
  const double sigma_t = config_.rotation_noise * std::sqrt(turn) +
                         config_.rotation_per_metre_noise_deg * M_PI / 180.0 * std::sqrt(dist);
  const Pose2 measured(motion.x * scale + sigma_xy * n_x, motion.y * scale + sigma_xy * n_y,
                       motion.theta * rot_scale + sigma_t * (0.7 * n_t + 0.7 * n_tm));
  pose_ = pose_ * measured;
  return pose_;
}

}  // namespace houghloc
