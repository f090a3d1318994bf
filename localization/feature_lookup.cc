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
  NearestFeatureSearch search(field);
  for (int r = 0; r < rows_; ++r) {
    for (int c = 0; c < cols_; ++c) {
      const Eigen::Vector2d centre = origin_ + resolution_m * Eigen::Vector2d(c + 0.5, r + 0.5);
      const FeatureRef f = search.nearest(centre).feature;
      cells_[static_cast<std::size_t>(r) * cols_ + c] =
          f.index < 0 ? -1 : static_cast<std::int16_t>(f.index * 4 + static_cast<int>(f.kind));
    }
  }
}

FeatureLookup::Residual FeatureLookup::residualBeyond(const Eigen::Vector2d& p, int code) const {
  Residual out;
  const FeatureRef f{static_cast<FeatureKind>(code & 3), code >> 2};
  Eigen::Vector2d q;
  if (f.kind == FeatureKind::kSegment) {  // beyond the segment's interior (see residual())
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
