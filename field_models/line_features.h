#pragma once

#include <Eigen/Core>

namespace houghloc {

/// A straight line segment between two points (centre-line coordinates, m).
struct Segment2 {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();

  double length() const { return (b - a).norm(); }
  /// Unit direction from a to b (zero for a degenerate segment).
  Eigen::Vector2d direction() const;
  Eigen::Vector2d closestPoint(const Eigen::Vector2d& p) const;
  double distanceTo(const Eigen::Vector2d& p) const { return (closestPoint(p) - p).norm(); }
};

/// A circular arc, counter-clockwise from start_rad over sweep_rad (DESIGN §4).
struct Arc2 {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double radius = 0.0;     ///< m
  double start_rad = 0.0;  ///< in (-pi, pi]
  double sweep_rad = 0.0;  ///< in (0, 2 pi]

  bool isFullCircle() const;
  /// True when the direction `angle_rad` seen from the centre lies on the arc.
  bool containsAngle(double angle_rad) const;
  Eigen::Vector2d pointAt(double angle_rad) const;
  Eigen::Vector2d closestPoint(const Eigen::Vector2d& p) const;
  double distanceTo(const Eigen::Vector2d& p) const { return (closestPoint(p) - p).norm(); }
  double length() const { return radius * sweep_rad; }
};

enum class MarkShape { kCross = 0, kDot = 1 };

/// A penalty or centre mark: a cross of two bars of length `size`, or a filled dot of diameter
/// `size`.
struct Mark {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double size = 0.1;  ///< m
  MarkShape shape = MarkShape::kCross;

  /// Distance from p to the painted mark (0 inside a dot; to the nearer bar of a cross).
  double distanceTo(const Eigen::Vector2d& p) const;
};

/// A goal, for display and for the renderer; not a line feature.
struct Goal {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< middle of the goal line, m
  double inner_width = 1.5;                          ///< between the posts' inner sides, m
  double post_diameter = 0.1;                        ///< m
  double height = 0.8;                               ///< m
  double depth = 0.5;                                ///< net depth behind the goal line, m
};

}  // namespace houghloc
