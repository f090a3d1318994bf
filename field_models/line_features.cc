#include "field_models/line_features.h"

#include <algorithm>
#include <cmath>

#include "field_models/pose2.h"

namespace houghloc {

Eigen::Vector2d Segment2::direction() const {
  const Eigen::Vector2d d = b - a;
  const double n = d.norm();
  return n > 0.0 ? Eigen::Vector2d(d / n) : Eigen::Vector2d::Zero();
}

Eigen::Vector2d Segment2::closestPoint(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d d = b - a;
  const double len2 = d.squaredNorm();
  if (len2 <= 0.0) return a;
  const double t = std::clamp((p - a).dot(d) / len2, 0.0, 1.0);
  return a + t * d;
}

bool Arc2::isFullCircle() const { return sweep_rad >= 2.0 * M_PI - 1e-9; }

bool Arc2::containsAngle(double angle_rad) const {
  if (isFullCircle()) return true;
  double offset = angle_rad - start_rad;
  offset -= 2.0 * M_PI * std::floor(offset / (2.0 * M_PI));  // [0, 2 pi)
  return offset <= sweep_rad;
}

Eigen::Vector2d Arc2::pointAt(double angle_rad) const {
  return center + radius * Eigen::Vector2d(std::cos(angle_rad), std::sin(angle_rad));
}

Eigen::Vector2d Arc2::closestPoint(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d d = p - center;
  const double angle = d.squaredNorm() > 0.0 ? std::atan2(d.y(), d.x()) : start_rad;
  if (containsAngle(angle)) return pointAt(angle);
  const Eigen::Vector2d first = pointAt(start_rad);
  const Eigen::Vector2d last = pointAt(start_rad + sweep_rad);
  return (first - p).squaredNorm() <= (last - p).squaredNorm() ? first : last;
}

double Mark::distanceTo(const Eigen::Vector2d& p) const {
  if (shape == MarkShape::kDot) return std::max(0.0, (p - center).norm() - 0.5 * size);
  const double h = 0.5 * size;
  const Segment2 along_x{center - Eigen::Vector2d(h, 0.0), center + Eigen::Vector2d(h, 0.0)};
  const Segment2 along_y{center - Eigen::Vector2d(0.0, h), center + Eigen::Vector2d(0.0, h)};
  return std::min(along_x.distanceTo(p), along_y.distanceTo(p));
}

}  // namespace houghloc
