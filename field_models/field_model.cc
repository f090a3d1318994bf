#include "field_models/field_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace houghloc {

std::string describeFeature(const FeatureRef& feature) {
  const char* list = feature.kind == FeatureKind::kSegment ? "segments"
                     : feature.kind == FeatureKind::kArc   ? "arcs"
                                                           : "marks";
  return std::string(list) + "[" + std::to_string(feature.index) + "]";
}

double rangeToRectangle(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                        double half_x, double half_y) {
  if (!(std::abs(origin.x()) <= half_x && std::abs(origin.y()) <= half_y)) return 0.0;
  // From inside, the ray leaves through the nearer of the two walls it runs towards.
  double range = std::numeric_limits<double>::infinity();
  if (direction.x() != 0.0) {
    range = std::min(range, (std::copysign(half_x, direction.x()) - origin.x()) / direction.x());
  }
  if (direction.y() != 0.0) {
    range = std::min(range, (std::copysign(half_y, direction.y()) - origin.y()) / direction.y());
  }
  return std::isfinite(range) ? range : 0.0;
}

}  // namespace houghloc
