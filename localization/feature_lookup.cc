#include "localization/feature_lookup.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "field_models/field_distance.h"

namespace houghloc {

FeatureLookup::FeatureLookup(const FieldModel& field, double resolution_m, double margin_m)
    : field_copy_(field), resolution_(resolution_m), inv_resolution_(1.0 / resolution_m) {
  const double hx = field.outerHalfLength() + margin_m, hy = field.outerHalfWidth() + margin_m;
  origin_ = Eigen::Vector2d(-hx, -hy);
  for (const Segment2& s : field.segments) lines_.push_back({s.a, s.direction(), s.length()});
  cols_ = static_cast<int>(std::ceil(2.0 * hx / resolution_m));
  rows_ = static_cast<int>(std::ceil(2.0 * hy / resolution_m));
  // A cell holds index * 4 + kind in 16 bits; no field map comes near this many features.
  const std::size_t most = std::max({field.segments.size(), field.arcs.size(), field.marks.size()});
  if (most >= 8192) throw std::invalid_argument("FeatureLookup: more than 8191 features of a kind");
  cells_.resize(static_cast<std::size_t>(cols_) * rows_);
  for (int r = 0; r < rows_; ++r) {
    for (int c = 0; c < cols_; ++c) {
      const Eigen::Vector2d centre = origin_ + resolution_m * Eigen::Vector2d(c + 0.5, r + 0.5);
      const FeatureRef f = nearestFeature(field, centre).feature;
      cells_[static_cast<std::size_t>(r) * cols_ + c] =
          f.index < 0 ? -1 : static_cast<std::int16_t>(f.index * 4 + static_cast<int>(f.kind));
    }
  }
}

FeatureLookup::Residual FeatureLookup::residual(const Eigen::Vector2d& p) const {
  Residual out;
  if (cells_.empty() || !p.allFinite()) return out;
  const int c = std::clamp(static_cast<int>((p.x() - origin_.x()) * inv_resolution_), 0, cols_ - 1);
  const int r = std::clamp(static_cast<int>((p.y() - origin_.y()) * inv_resolution_), 0, rows_ - 1);
  const int code = cells_[static_cast<std::size_t>(r) * cols_ + c];
  if (code < 0) return out;
  const FeatureRef f{static_cast<FeatureKind>(code & 3), code >> 2};
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
