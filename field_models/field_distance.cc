#include "field_models/field_distance.h"

namespace houghloc {

Eigen::Vector2d closestPointOnMark(const Mark& mark, const Eigen::Vector2d& p) {
  if (mark.shape == MarkShape::kDot) {
    const Eigen::Vector2d d = p - mark.center;
    const double r = 0.5 * mark.size;
    return d.norm() <= r ? p : Eigen::Vector2d(mark.center + d.normalized() * r);
  }
  const double h = 0.5 * mark.size;
  const Segment2 along_x{mark.center - Eigen::Vector2d(h, 0.0), mark.center + Eigen::Vector2d(h, 0.0)};
  const Segment2 along_y{mark.center - Eigen::Vector2d(0.0, h), mark.center + Eigen::Vector2d(0.0, h)};
  const Eigen::Vector2d cx = along_x.closestPoint(p), cy = along_y.closestPoint(p);
  return (cx - p).squaredNorm() <= (cy - p).squaredNorm() ? cx : cy;
}

NearestFeature nearestFeature(const FieldModel& field, const Eigen::Vector2d& p_field) {
  NearestFeature best;
  auto consider = [&](FeatureKind kind, int index, const Eigen::Vector2d& closest) {
    const double d = (closest - p_field).norm();
    if (d < best.distance_m) best = NearestFeature{FeatureRef{kind, index}, d, closest};
  };
  for (int i = 0; i < static_cast<int>(field.segments.size()); ++i) {
    consider(FeatureKind::kSegment, i, field.segments[i].closestPoint(p_field));
  }
  for (int i = 0; i < static_cast<int>(field.arcs.size()); ++i) {
    consider(FeatureKind::kArc, i, field.arcs[i].closestPoint(p_field));
  }
  for (int i = 0; i < static_cast<int>(field.marks.size()); ++i) {
    consider(FeatureKind::kMark, i, closestPointOnMark(field.marks[i], p_field));
  }
  return best;
}

}  // namespace houghloc
