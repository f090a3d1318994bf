#pragma once

#include <string>
#include <vector>

#include "field_models/field_model.h"

namespace houghloc {

struct FieldValidationConfig {
  double min_segment_length_m = 1e-3;   ///< shorter segments count as degenerate
  double duplicate_tolerance_m = 1e-6;  ///< endpoints this close are the same point
  /// How far a feature may reach beyond the field plus border strip before it is "outside"
  /// (absorbs rounding in hand-written maps), m.
  double outside_tolerance_m = 1e-6;
};

/// One problem with a map: which entry and what is wrong with it.
struct FieldIssue {
  std::string where;    ///< e.g. "segments[2]", "line_width", "map"
  std::string problem;  ///< e.g. "zero length"

  std::string toString() const { return where + ": " + problem; }
};

/// Checks a map's geometry: finite numbers, positive dimensions and line width, degenerate and
/// duplicate or overlapping segments, arcs with a bad radius, start or sweep (DESIGN §4 ranges),
/// marks and goals with bad sizes, and features outside the field plus border strip. An empty
/// result means the map is usable; the standard fields give none.
std::vector<FieldIssue> validateField(const FieldModel& field,
                                      const FieldValidationConfig& config = {});

}  // namespace houghloc
