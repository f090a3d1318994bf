#pragma once

#include <string>
#include <vector>

#include "field_models/field_model.h"

namespace houghloc {

/// The dimensions the rules give for a field (DESIGN §4 table), all in metres. Areas are measured
/// to the lines' centres like every other coordinate; a zero goal area means "none" (SPL 2019).
struct FieldDimensions {
  std::string name;
  double length = 9.0;                 ///< between goal lines
  double width = 6.0;                  ///< between touch lines
  double line_width = 0.05;
  double goal_area_length = 0.6;       ///< along x; 0 = no goal area
  double goal_area_width = 2.2;        ///< along y; 0 = no goal area
  double penalty_area_length = 1.65;   ///< along x
  double penalty_area_width = 4.0;     ///< along y
  double penalty_mark_distance = 1.3;  ///< from the goal line to the mark's centre
  double penalty_mark_size = 0.1;
  MarkShape penalty_mark_shape = MarkShape::kCross;
  double center_circle_diameter = 1.5;
  double border_strip_width = 0.7;
  double corner_arc_radius = 0.0;      ///< MSL quarter circles; 0 = none
  double goal_inner_width = 1.5;
  double goal_post_diameter = 0.1;
  double goal_height = 0.8;
  double goal_depth = 0.5;
};

/// Every line the rules draw for these dimensions: touch and goal lines, halfway line, centre
/// circle and mark, goal and penalty areas, penalty marks, corner arcs; plus both goals.
FieldModel makeField(const FieldDimensions& dims);

/// Names accepted by standardFieldDimensions(): spl, spl2019, kid, adult, msl.
std::vector<std::string> standardFieldNames();

/// Dimensions of a standard field; throws std::invalid_argument naming the unknown field.
FieldDimensions standardFieldDimensions(const std::string& name);

/// makeField(standardFieldDimensions(name)).
FieldModel makeStandardField(const std::string& name);

}  // namespace houghloc
