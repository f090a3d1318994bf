#pragma once

#include <Eigen/Core>
#include <cmath>

namespace houghloc {

/// Wraps an angle to (-pi, pi] (DESIGN §3), the general case (std::remainder).
double wrapAngle(double angle_rad);
/// Wraps an angle to (-pi, pi] (DESIGN §3). Inline with a fast path: every Pose2 is built through
/// it, and its angles are mostly in range already, where wrapAngle returns them unchanged (the
/// quotient by 2 pi is at most 1/2 in magnitude and rounds to 0, the tie at pi to even 0).
inline double normalizeAngle(double angle_rad) {
  if (angle_rad > -M_PI && angle_rad <= M_PI) return angle_rad;
  return wrapAngle(angle_rad);
}

/// A rigid 2-D transform a_T_b = (x, y, theta): p_a = Rz(theta) p_b + (x, y) (DESIGN §3).
/// Names carry the frames, e.g. `field_T_robot`; composition reads left to right:
/// field_T_camera = field_T_robot * robot_T_camera.
struct Pose2 {
  double x = 0.0;      ///< m
  double y = 0.0;      ///< m
  double theta = 0.0;  ///< rad, kept in (-pi, pi] by every operation here

  Pose2() = default;
  Pose2(double x_m, double y_m, double theta_rad)
      : x(x_m), y(y_m), theta(normalizeAngle(theta_rad)) {}

  Eigen::Vector2d translation() const { return {x, y}; }
  Eigen::Matrix2d rotation() const;

  /// p_a = a_T_b.transform(p_b).
  Eigen::Vector2d transform(const Eigen::Vector2d& p_b) const;
  Pose2 inverse() const;
  Pose2 operator*(const Pose2& b_T_c) const;

  bool isFinite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(theta); }
};

/// Smallest signed difference a - b of two angles, in (-pi, pi].
inline double angleDifference(double a_rad, double b_rad) { return normalizeAngle(a_rad - b_rad); }

}  // namespace houghloc
