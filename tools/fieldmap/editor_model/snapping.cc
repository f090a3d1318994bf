#include "tools/fieldmap/editor_model/snapping.h"

#include <cmath>
#include <vector>

namespace houghloc::fieldmap {
namespace {

/// The snap points of a feature: segment ends, arc/mark/goal centres, arc end points.
std::vector<Eigen::Vector2d> snapPointsOf(const EditorDocument& doc, const FeatureId& f) {
  switch (f.kind) {
    case EditorKind::kSegment:
      return {doc.segment(f).a, doc.segment(f).b};
    case EditorKind::kMark:
      return {doc.mark(f).center};
    case EditorKind::kGoal:
      return {doc.goal(f).center};
    case EditorKind::kArc: {
      const Arc2& arc = doc.arc(f);
      if (arc.isFullCircle()) return {arc.center};
      return {arc.center, arc.pointAt(arc.start_rad), arc.pointAt(arc.start_rad + arc.sweep_rad)};
    }
  }
  return {};
}

}  // namespace

SnapResult snapPoint(const EditorDocument& doc, const Eigen::Vector2d& point,
                     const std::optional<FeatureId>& dragged,
                     const std::optional<Eigen::Vector2d>& anchor, const SnapConfig& config) {
  SnapResult result{point, SnapKind::kNone, {}};
  if (!config.enabled) return result;

  double best = config.endpoint_radius_m;
  for (const FeatureId& f : doc.allFeatures()) {
    if (dragged && f == *dragged) continue;
    for (const Eigen::Vector2d& p : snapPointsOf(doc, f)) {
      const double d = (p - point).norm();
      if (d <= best) {
        best = d;
        result = {p, SnapKind::kEndpoint, f};
      }
    }
  }
  if (result.kind == SnapKind::kEndpoint) return result;

  if (anchor) {
    const Eigen::Vector2d v = point - *anchor;
    const double length = v.norm();
    double best_angle = config.angle_tolerance_rad;
    if (length > 0.0) {
      for (int i = 0; i < static_cast<int>(doc.ids(EditorKind::kSegment).size()); ++i) {
        const FeatureId f = doc.idAt(EditorKind::kSegment, i);
        if (dragged && f == *dragged) continue;
        const Eigen::Vector2d u = doc.segment(f).direction();
        if (u.isZero()) continue;
        const Eigen::Vector2d n(-u.y(), u.x());
        // Four candidate directions: +-u (parallel) and +-n (perpendicular).
        const std::pair<Eigen::Vector2d, SnapKind> candidates[] = {{u, SnapKind::kParallel},
                                                                   {-u, SnapKind::kParallel},
                                                                   {n, SnapKind::kPerpendicular},
                                                                   {-n, SnapKind::kPerpendicular}};
        for (const auto& [dir, kind] : candidates) {
          const double angle = std::acos(std::clamp(dir.dot(v) / length, -1.0, 1.0));
          if (angle < best_angle) {
            best_angle = angle;
            result = {*anchor + length * dir, kind, f};
          }
        }
      }
    }
    if (result.kind != SnapKind::kNone) return result;
  }

  if (config.grid_m > 0.0) {
    result.point = (point / config.grid_m).array().round().matrix() * config.grid_m;
    result.kind = SnapKind::kGrid;
  }
  return result;
}

}  // namespace houghloc::fieldmap
