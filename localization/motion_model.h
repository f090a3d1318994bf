#pragma once

#include "localization/gaussian_pose.h"

namespace houghloc {

/// Odometry noise of a walking robot. Variances grow linearly with the distance walked and the
/// angle turned (a random walk in the motion, so the model does not depend on the frame rate),
/// plus a small random walk in time that covers slip while standing. When the motion is unknown
/// (no odometry, a jump), a much larger random walk in time stands in for it.
struct MotionModelConfig {
  double trans_var_per_m = 0.01;    ///< translation variance per metre walked, m^2/m (10 cm/m)
  double trans_var_per_rad = 4e-4;  ///< translation variance per radian turned, m^2/rad
  double rot_var_per_rad = 0.0225;  ///< heading variance per radian turned, rad^2/rad
  double rot_var_per_m = 0.0025;    ///< heading variance per metre walked, rad^2/m
  double trans_var_per_s = 2.5e-5;  ///< random walk with odometry, m^2/s
  double rot_var_per_s = 2.5e-5;    ///< random walk with odometry, rad^2/s
  double unknown_trans_var_per_s = 0.0625;  ///< random walk without odometry, m^2/s (0.25 m/sqrt s)
  double unknown_rot_var_per_s = 0.25;      ///< random walk without odometry, rad^2/s
  double max_sigma_xy_m = 10.0;             ///< covariance is capped here so it stays finite, m
  double max_sigma_theta_rad = 3.2;         ///< rad (about pi: the heading is then unknown)
};

/// EKF prediction: field_T_robot' = field_T_robot * motion (DESIGN §3), motion in the robot
/// frame; covariance F P F^T + G Q G^T with F, G the Jacobians of the composition.
void predictWithMotion(const Pose2& motion, double dt_s, const MotionModelConfig& config,
                       GaussianPose* pose);

/// The motion over dt_s is unknown: isotropic random walk in position and heading.
void inflateUnknownMotion(double dt_s, const MotionModelConfig& config, GaussianPose* pose);

/// Symmetrises the covariance, caps its variances at the configured maxima and repairs
/// non-finite or non-positive entries, so no NaN can leave the tracker.
void sanitizeCovariance(const MotionModelConfig& config, Eigen::Matrix3d* covariance);

}  // namespace houghloc
