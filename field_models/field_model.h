#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "field_models/line_features.h"

namespace houghloc {

/// A field-line map in the field frame (DESIGN §3, §4): origin at the centre mark, x toward the
/// opponent goal. Line coordinates are centre lines; `line_width` is the painted width.
struct FieldModel {
  std::string name;
  double field_length = 9.0;        ///< between goal lines, m
  double field_width = 6.0;         ///< between touch lines, m
  double line_width = 0.05;         ///< m
  double border_strip_width = 0.7;  ///< green beyond the lines, m

  std::vector<Segment2> segments;
  std::vector<Arc2> arcs;
  std::vector<Mark> marks;
  std::vector<Goal> goals;

  double halfLength() const { return 0.5 * field_length; }
  double halfWidth() const { return 0.5 * field_width; }
  /// Half extents of the field plus its border strip (the carpet), m.
  double outerHalfLength() const { return halfLength() + border_strip_width; }
  double outerHalfWidth() const { return halfWidth() + border_strip_width; }
};

/// Which line feature of a FieldModel something refers to.
enum class FeatureKind { kSegment, kArc, kMark };

struct FeatureRef {
  FeatureKind kind = FeatureKind::kSegment;
  int index = -1;  ///< into FieldModel::segments, arcs or marks; -1 when there is none
};

/// Human-readable name of a feature for messages, e.g. "segments[3]".
std::string describeFeature(const FeatureRef& feature);

/// Distance from `origin` along the unit `direction` to the border of the rectangle
/// |x| <= half_x, |y| <= half_y (e.g. the carpet, outerHalfLength() x outerHalfWidth(), field
/// frame); 0 when origin lies outside it.
/// Inline: the global localizer calls it for every field-edge sample of every candidate pose.
inline double rangeToRectangle(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                               double half_x, double half_y) {
  if (!(std::abs(origin.x()) <= half_x && std::abs(origin.y()) <= half_y)) return 0.0;
  // From inside, the ray leaves through the nearer of the two walls it runs towards.
  const double to_x = direction.x() != 0.0
                          ? (std::copysign(half_x, direction.x()) - origin.x()) / direction.x()
                          : std::numeric_limits<double>::infinity();
  const double to_y = direction.y() != 0.0
                          ? (std::copysign(half_y, direction.y()) - origin.y()) / direction.y()
                          : std::numeric_limits<double>::infinity();
  const double range = std::min(to_x, to_y);
  return std::isfinite(range) ? range : 0.0;
}

}  // namespace houghloc
