#include "localization/motion_model.h"

#include <algorithm>
#include <cmath>

namespace houghloc {

void predictWithMotion(const Pose2& motion, double dt_s, const MotionModelConfig& config,
                       GaussianPose* pose) {
  if (!motion.isFinite()) return;
  const double c = std::cos(pose->mean.theta), s = std::sin(pose->mean.theta);
  const double trans = std::hypot(motion.x, motion.y), rot = std::abs(motion.theta);
  const double dt = std::isfinite(dt_s) ? std::max(dt_s, 0.0) : 0.0;
  const double var_t =
      config.trans_var_per_m * trans + config.trans_var_per_rad * rot + config.trans_var_per_s * dt;
  const double var_r =
      config.rot_var_per_rad * rot + config.rot_var_per_m * trans + config.rot_var_per_s * dt;
  const Eigen::Vector3d q(var_t, var_t, var_r);  // robot frame, isotropic in translation
  Eigen::Matrix3d f = Eigen::Matrix3d::Identity();
  f(0, 2) = -s * motion.x - c * motion.y;
  f(1, 2) = c * motion.x - s * motion.y;
  Eigen::Matrix3d g = Eigen::Matrix3d::Identity();
  g.topLeftCorner<2, 2>() << c, -s, s, c;
  pose->covariance = f * pose->covariance * f.transpose() + g * q.asDiagonal() * g.transpose();
  pose->mean = pose->mean * motion;
  sanitizeCovariance(config, &pose->covariance);
}

void inflateUnknownMotion(double dt_s, const MotionModelConfig& config, GaussianPose* pose) {
  if (!std::isfinite(dt_s) || dt_s <= 0.0) return;
  const double vt = config.unknown_trans_var_per_s * dt_s;
  const double vr = config.unknown_rot_var_per_s * dt_s;
  pose->covariance += Eigen::Vector3d(vt, vt, vr).asDiagonal();
  sanitizeCovariance(config, &pose->covariance);
}

void sanitizeCovariance(const MotionModelConfig& config, Eigen::Matrix3d* covariance) {
  Eigen::Matrix3d& p = *covariance;
  if (!p.allFinite()) p = Eigen::Matrix3d::Zero();
  p = 0.5 * (p + p.transpose()).eval();
  const double max_xy = config.max_sigma_xy_m * config.max_sigma_xy_m;
  const double max_theta = config.max_sigma_theta_rad * config.max_sigma_theta_rad;
  const Eigen::Vector3d max_var(max_xy, max_xy, max_theta);
  constexpr double kMinVariance = 1e-10;  // keeps the matrix invertible
  for (int i = 0; i < 3; ++i) {
    const double v = std::clamp(p(i, i), kMinVariance, max_var(i));
    if (v != p(i, i)) {
      // Scale row and column so the correlations survive the clamp.
      const double scale = p(i, i) > 0.0 ? std::sqrt(v / p(i, i)) : 0.0;
      p.row(i) *= scale;
      p.col(i) *= scale;
      p(i, i) = v;
    }
  }
  // Correlations above 1 (rounding) would make the matrix indefinite.
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      const double bound = 0.999 * std::sqrt(p(i, i) * p(j, j));
      p(i, j) = p(j, i) = std::clamp(p(i, j), -bound, bound);
    }
  }
}

}  // namespace houghloc
