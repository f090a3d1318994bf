#include "field_models/pose3.h"

#include <Eigen/Geometry>
#include <cmath>

namespace houghloc {

Eigen::Matrix3d Pose3::rotation() const {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Vector3d Pose3::transform(const Eigen::Vector3d& p_b) const {
  return rotation() * p_b + translation();
}

bool Pose3::isFinite() const {
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z) && std::isfinite(roll) &&
         std::isfinite(pitch) && std::isfinite(yaw);
}

}  // namespace houghloc
