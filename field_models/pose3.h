#pragma once

#include <Eigen/Core>

namespace houghloc {

/// A 3-D rigid transform given as translation and roll/pitch/yaw (DESIGN §3), used for
/// `robot_T_camera`: p_robot = R p_cam + (x, y, z) with R = Rz(yaw) Ry(pitch) Rx(roll).
/// In the camera body frame x is the optical axis, y left, z up, so positive pitch looks down.
struct Pose3 {
  double x = 0.0, y = 0.0, z = 0.0;              ///< m
  double roll = 0.0, pitch = 0.0, yaw = 0.0;     ///< rad

  Eigen::Matrix3d rotation() const;
  Eigen::Vector3d translation() const { return {x, y, z}; }
  /// p_a = a_T_b.transform(p_b).
  Eigen::Vector3d transform(const Eigen::Vector3d& p_b) const;
  bool isFinite() const;
};

}  // namespace houghloc
