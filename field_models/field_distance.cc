#include "field_models/field_distance.h"

#include <cmath>
#include <limits>

namespace houghloc {

Eigen::Vector2d closestPointOnMark(const Mark& mark, const Eigen::Vector2d& p) {
  if (mark.shape == MarkShape::kDot) {
    const Eigen::Vector2d d = p - mark.center;
    const double r = 0.5 * mark.size;
    return d.norm() <= r ? p : Eigen::Vector2d(mark.center + d.normalized() * r);
  }
  const double h = 0.5 * mark.size;
  const Segment2 along_x{mark.center - Eigen::Vector2d(h, 0.0),
                         mark.center + Eigen::Vector2d(h, 0.0)};
  const Segment2 along_y{mark.center - Eigen::Vector2d(0.0, h),
                         mark.center + Eigen::Vector2d(0.0, h)};
  const Eigen::Vector2d cx = along_x.closestPoint(p), cy = along_y.closestPoint(p);
  return (cx - p).squaredNorm() <= (cy - p).squaredNorm() ? cx : cy;
}

namespace {

Eigen::Vector2d closestPointOn(const FieldModel& field, const FeatureRef& f,
                               const Eigen::Vector2d& p) {
  switch (f.kind) {
    case FeatureKind::kSegment:
      return field.segments[f.index].closestPoint(p);
    case FeatureKind::kArc:
      return field.arcs[f.index].closestPoint(p);
    case FeatureKind::kMark:
      break;
  }
  return closestPointOnMark(field.marks[f.index], p);
}

/// Calls visit(FeatureRef) for every line feature: segments, arcs, marks (the map's order).
template <typename Visit>
void forEachFeature(const FieldModel& field, Visit&& visit) {
  for (int i = 0; i < static_cast<int>(field.segments.size()); ++i) {
    visit(FeatureRef{FeatureKind::kSegment, i});
  }
  for (int i = 0; i < static_cast<int>(field.arcs.size()); ++i) {
    visit(FeatureRef{FeatureKind::kArc, i});
  }
  for (int i = 0; i < static_cast<int>(field.marks.size()); ++i) {
    visit(FeatureRef{FeatureKind::kMark, i});
  }
}

// A lower bound is trusted to skip a feature only when it exceeds the best distance by this much
// (m): far more than the rounding of either computation, far less than any grid cell.
constexpr double kBoundSlackM = 1e-9;

}  // namespace

NearestFeature nearestFeature(const FieldModel& field, const Eigen::Vector2d& p_field) {
  NearestFeature best;
  forEachFeature(field, [&](const FeatureRef& f) {
    const Eigen::Vector2d closest = closestPointOn(field, f, p_field);
    const double d = (closest - p_field).norm();
    if (d < best.distance_m) best = NearestFeature{f, d, closest};
  });
  return best;
}

NearestFeatureSearch::NearestFeatureSearch(const FieldModel& field) : field_(field) {
  forEachFeature(field, [&](const FeatureRef& f) { features_.push_back(f); });
  for (const FeatureRef& f : features_) {
    Bound b;
    if (f.kind == FeatureKind::kSegment) {
      const Segment2& s = field.segments[f.index];
      b.low = s.a.cwiseMin(s.b);
      b.high = s.a.cwiseMax(s.b);
    } else if (f.kind == FeatureKind::kArc) {
      b.low = b.high = field.arcs[f.index].center;
      b.radius = field.arcs[f.index].radius;
    } else {
      const Mark& m = field.marks[f.index];
      b.low = m.center - Eigen::Vector2d::Constant(0.5 * m.size);
      b.high = m.center + Eigen::Vector2d::Constant(0.5 * m.size);
    }
    bounds_.push_back(b);
  }
}

double NearestFeatureSearch::lowerBound(const Bound& bound, const Eigen::Vector2d& p) const {
  // An arc lies on its circle; a segment and a mark inside their box.
  if (bound.radius >= 0.0) return std::abs((p - bound.low).norm() - bound.radius);
  const Eigen::Vector2d outside =
      (bound.low - p).cwiseMax(p - bound.high).cwiseMax(Eigen::Vector2d::Zero());
  return outside.norm();
}

NearestFeature NearestFeatureSearch::nearest(const Eigen::Vector2d& p_field) {
  if (features_.empty() || !p_field.allFinite()) return nearestFeature(field_, p_field);
  NearestFeature best;
  std::size_t best_i = last_;
  best.closest_point = closestPointOn(field_, features_[last_], p_field);
  best.distance_m = (best.closest_point - p_field).norm();
  best.feature = features_[last_];
  for (std::size_t i = 0; i < features_.size(); ++i) {
    if (i == last_ || lowerBound(bounds_[i], p_field) > best.distance_m + kBoundSlackM) continue;
    const Eigen::Vector2d closest = closestPointOn(field_, features_[i], p_field);
    const double d = (closest - p_field).norm();
    // nearestFeature() keeps the first of equal distances in the map's order.
    if (d < best.distance_m || (d == best.distance_m && i < best_i)) {
      best = NearestFeature{features_[i], d, closest};
      best_i = i;
    }
  }
  last_ = best_i;
  // Every distance infinite (a point beyond 1e154 m): nearestFeature() finds no feature either.
  return best.distance_m < std::numeric_limits<double>::infinity() ? best : NearestFeature{};
}

}  // namespace houghloc
