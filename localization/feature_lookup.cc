#include "localization/feature_lookup.h"

#include <algorithm>
#include <cmath>

#include "field_models/field_distance.h"

namespace houghloc {

FeatureLookup::FeatureLookup(const FieldModel& field, double resolution_m, double margin_m)
    : field_copy_(field), resolution_(resolution_m), inv_resolution_(1.0 / resolution_m) {
  const double hx = field.outerHalfLength() + margin_m, hy = field.outerHalfWidth() + margin_m;
  origin_ = Eigen::Vector2d(-hx, -hy);
  for (const Segment2& s : field.segments) lines_.push_back({s.a, s.direction(), s.length()});
  cols_ = static_cast<int>(std::ceil(2.0 * hx / resolution_m));
  rows_ = static_cast<int>(std::ceil(2.0 * hy / resolution_m));
  cells_.resize(static_cast<std::size_t>(cols_) * rows_);
  for (int r = 0; r < rows_; ++r) {
    for (int c = 0; c < cols_; ++c) {
      const Eigen::Vector2d centre = origin_ + resolution_m * Eigen::Vector2d(c + 0.5, r + 0.5);
      cells_[static_cast<std::size_t>(r) * cols_ + c] = nearestFeature(field, centre).feature;
    }
  }
}

FeatureLookup::Residual FeatureLookup::residual(const Eigen::Vector2d& p) const {
  Residual out;
  if (cells_.empty() || !p.allFinite()) return out;
  const int c = std::clamp(static_cast<int>((p.x() - origin_.x()) * inv_resolution_), 0, cols_ - 1);
  const int r = std::clamp(static_cast<int>((p.y() - origin_.y()) * inv_resolution_), 0, rows_ - 1);
  const FeatureRef& f = cells_[static_cast<std::size_t>(r) * cols_ + c];
  if (f.index < 0) return out;
  Eigen::Vector2d q;
  if (f.kind == FeatureKind::kSegment) {
    // Signed point-to-line distance inside the segment: smooth across the line for Gauss-Newton.
    const Line& line = lines_[f.index];
    const double t = (p - line.a).dot(line.u);
    if (t > 0.0 && t < line.length) {
      out.direction = Eigen::Vector2d(-line.u.y(), line.u.x());
      out.distance_m = out.direction.dot(p - line.a);
      out.valid = true;
      return out;
    }
    q = field_copy_.segments[f.index].closestPoint(p);
  } else if (f.kind == FeatureKind::kArc) {
    const Arc2& arc = field_copy_.arcs[f.index];
    const Eigen::Vector2d v = p - arc.center;
    const double n = v.norm();
    if (n > 1e-9 && (arc.isFullCircle() || arc.containsAngle(std::atan2(v.y(), v.x())))) {
      out.direction = v / n;
      out.distance_m = n - arc.radius;
      out.valid = true;
      return out;
    }
    q = arc.closestPoint(p);
  } else {
    q = closestPointOnMark(field_copy_.marks[f.index], p);
  }
  const Eigen::Vector2d d = p - q;
  out.distance_m = d.norm();
  out.direction =
      out.distance_m > 1e-12 ? Eigen::Vector2d(d / out.distance_m) : Eigen::Vector2d::Zero();
  out.valid = true;
  return out;
}

}  // namespace houghloc
