#pragma once

#include <Eigen/Core>
#include <optional>

#include "tools/fieldmap/editor_model/editor_document.h"

namespace houghloc::fieldmap {

struct SnapConfig {
  bool enabled = true;
  double grid_m = 0.05;               ///< grid pitch; 0 = no grid snapping
  double endpoint_radius_m = 0.10;    ///< endpoints and centres this close pull the point on them
  double angle_tolerance_rad = 0.05;  ///< directions this close to parallel/perpendicular snap
};

enum class SnapKind { kNone, kGrid, kEndpoint, kParallel, kPerpendicular };

struct SnapResult {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  SnapKind kind = SnapKind::kNone;
  FeatureId target;  ///< the feature snapped to (endpoint, parallel, perpendicular)
};

/// Where a dragged point lands. Priority: another feature's endpoint (or arc/mark centre) within
/// endpoint_radius_m; else, when `anchor` is given (the other end of the segment being dragged),
/// the direction anchor->point turned onto the nearest segment direction that is parallel or
/// perpendicular within angle_tolerance_rad, keeping the length; else the grid. `dragged` is left
/// out of the endpoint and direction search.
SnapResult snapPoint(const EditorDocument& doc, const Eigen::Vector2d& point,
                     const std::optional<FeatureId>& dragged,
                     const std::optional<Eigen::Vector2d>& anchor, const SnapConfig& config);

}  // namespace houghloc::fieldmap
