#pragma once

#include <Eigen/Core>
#include <cmath>

#include "field_models/pose2.h"
#include "localization/pose_hypothesis.h"

namespace houghloc {

/// A pose estimate with its uncertainty: the unit the tracker exchanges with the outside. Global
/// hypotheses come in as these, hints carry them, tracked hypotheses extend them.
struct GaussianPose {
  Pose2 mean;  ///< field_T_robot
  /// Over (x m, y m, theta rad): m^2, m rad, rad^2.
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity() * 0.01;
  double weight = 1.0;  ///< relative, >= 0

  bool isFinite() const {
    return mean.isFinite() && covariance.allFinite() && std::isfinite(weight);
  }
};

/// The point-symmetric twin (-x, -y, theta + pi) of a pose on a point-symmetric field.
inline Pose2 mirrored(const Pose2& pose) { return Pose2(-pose.x, -pose.y, pose.theta + M_PI); }

/// Covariance of the mirrored pose: the Jacobian diag(-1, -1, 1) flips the sign of the x-theta
/// and y-theta covariances and keeps the rest.
inline Eigen::Matrix3d mirroredCovariance(const Eigen::Matrix3d& covariance) {
  const Eigen::Vector3d flip(-1.0, -1.0, 1.0);
  return flip.asDiagonal() * covariance * flip.asDiagonal();
}

/// Mirror of a Gaussian (mean and covariance).
inline GaussianPose mirrored(const GaussianPose& pose) {
  GaussianPose out = pose;
  out.mean = mirrored(pose.mean);
  out.covariance = mirroredCovariance(pose.covariance);
  return out;
}

/// Mirror of a global hypothesis: pose, covariance and the direction along its lines.
inline PoseHypothesis mirrored(const PoseHypothesis& hypothesis) {
  PoseHypothesis out = hypothesis;
  out.field_T_robot = mirrored(hypothesis.field_T_robot);
  out.covariance = mirroredCovariance(hypothesis.covariance);
  out.line_direction = -hypothesis.line_direction;
  return out;
}

/// a - b on the manifold: (dx, dy, wrapped dtheta).
inline Eigen::Vector3d poseDifference(const Pose2& a, const Pose2& b) {
  return {a.x - b.x, a.y - b.y, angleDifference(a.theta, b.theta)};
}

/// pose + delta on the manifold (additive in x, y; theta wrapped).
inline Pose2 poseAdd(const Pose2& pose, const Eigen::Vector3d& delta) {
  return Pose2(pose.x + delta.x(), pose.y + delta.y(), pose.theta + delta.z());
}

}  // namespace houghloc
