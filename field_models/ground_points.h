#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace houghloc {

/// One field-line point seen by a camera, projected onto the ground plane (DESIGN §2, §3).
struct GroundPoint {
  Eigen::Vector2d p_robot = Eigen::Vector2d::Zero();  ///< m, robot frame
  double weight = 1.0;                                ///< relative confidence, > 0
  Eigen::Vector2f pixel = Eigen::Vector2f::Zero();    ///< source pixel (u, v), distorted image
  int camera_id = 0;
  /// How p_robot moves when the camera's recorded roll (column 0) and pitch (column 1) are off
  /// (DESIGN §3 Pose3 angles), m/rad: a pitch error moves far points along their rays by
  /// (range^2 + height^2) / height times the angle. Lets localization tell a tilted camera from
  /// a moved robot. Zero when unknown (no tilt is then inferred from the point).
  Eigen::Matrix2d tilt_jacobian = Eigen::Matrix2d::Zero();
};

/// The point's tilt Jacobian where it is finite, else zero: a point whose Jacobian is broken
/// tells nothing about the tilt, but still counts as a point.
inline Eigen::Matrix2d usableTiltJacobian(const GroundPoint& point) {
  return point.tilt_jacobian.allFinite() ? point.tilt_jacobian : Eigen::Matrix2d::Zero();
}

/// A closed polygon on the ground in the robot frame (m), vertices in order.
using GroundPolygon = std::vector<Eigen::Vector2d>;

/// Where a camera saw the green carpet end (the field boundary) in one image column, projected
/// to the ground. Known to a few pixels in the image, so along the viewing ray to
/// range_sigma_m, which grows with the square of the range; something standing on the field
/// (a robot, a referee) can make it nearer than the carpet's edge, never farther.
struct FieldEdgePoint {
  Eigen::Vector2d p_robot = Eigen::Vector2d::Zero();  ///< m, robot frame
  double range_sigma_m = 0.0;                         ///< 1 sigma along the ray from the robot
  int camera_id = 0;
};

/// Everything one frame's vision says about the ground: the line points, and the part of the
/// ground the cameras actually saw (field boundary and image border projected to the ground),
/// which lets localization use negative evidence (lines expected there but not seen).
struct GroundPoints {
  std::int64_t t_us = 0;
  std::vector<GroundPoint> points;
  std::vector<GroundPolygon> visible_regions;  ///< one per camera; empty when unknown
  /// The carpet's edge at any range (the visible regions stop at the points' maximum range);
  /// empty when not measured.
  std::vector<FieldEdgePoint> field_edge;

  std::size_t size() const { return points.size(); }
  bool empty() const { return points.empty(); }
};

/// True when p lies inside the polygon (even-odd rule).
bool insidePolygon(const GroundPolygon& polygon, const Eigen::Vector2d& p);

}  // namespace houghloc
