#include "field_models/pose2.h"

#include <Eigen/Geometry>

namespace houghloc {

double wrapAngle(double angle_rad) {
  if (!std::isfinite(angle_rad)) return angle_rad;
  double wrapped = std::remainder(angle_rad, 2.0 * M_PI);  // in [-pi, pi]
  if (wrapped <= -M_PI) wrapped += 2.0 * M_PI;
  return wrapped;
}

Eigen::Matrix2d Pose2::rotation() const { return Eigen::Rotation2Dd(theta).toRotationMatrix(); }

Eigen::Vector2d Pose2::transform(const Eigen::Vector2d& p_b) const {
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * p_b.x() - s * p_b.y() + x, s * p_b.x() + c * p_b.y() + y};
}

Pose2 Pose2::inverse() const {
  const double c = std::cos(theta), s = std::sin(theta);
  return Pose2(-c * x - s * y, s * x - c * y, -theta);
}

Pose2 Pose2::operator*(const Pose2& b_T_c) const {
  const Eigen::Vector2d t = transform(b_T_c.translation());
  return Pose2(t.x(), t.y(), theta + b_T_c.theta);
}

}  // namespace houghloc
