#include "field_models/standard_fields.h"

#include <cmath>
#include <stdexcept>

namespace houghloc {
namespace {

Segment2 segment(double x1, double y1, double x2, double y2) {
  return Segment2{Eigen::Vector2d(x1, y1), Eigen::Vector2d(x2, y2)};
}

/// The three lines of a box in front of the goal line at x = side * hl (side = +1 or -1): two
/// lines along x from the goal line and the front line parallel to it. The goal line itself
/// already closes the box.
void addBox(double hl, double side, double box_length, double box_width,
            std::vector<Segment2>& out) {
  const double goal_x = side * hl;
  const double front_x = side * (hl - box_length);
  const double hw = 0.5 * box_width;
  out.push_back(segment(front_x, -hw, front_x, hw));
  out.push_back(segment(goal_x, hw, front_x, hw));
  out.push_back(segment(goal_x, -hw, front_x, -hw));
}

FieldDimensions withName(FieldDimensions dims, const char* name) {
  dims.name = name;
  return dims;
}

}  // namespace

FieldModel makeField(const FieldDimensions& d) {
  FieldModel field;
  field.name = d.name;
  field.field_length = d.length;
  field.field_width = d.width;
  field.line_width = d.line_width;
  field.border_strip_width = d.border_strip_width;
  const double hl = 0.5 * d.length, hw = 0.5 * d.width;

  auto& s = field.segments;
  s.push_back(segment(-hl, hw, hl, hw));    // left touch line
  s.push_back(segment(-hl, -hw, hl, -hw));  // right touch line
  s.push_back(segment(-hl, -hw, -hl, hw));  // own goal line
  s.push_back(segment(hl, -hw, hl, hw));    // opponent goal line
  s.push_back(segment(0.0, -hw, 0.0, hw));  // halfway line
  for (double side : {-1.0, 1.0}) {
    if (d.goal_area_length > 0.0 && d.goal_area_width > 0.0) {
      addBox(hl, side, d.goal_area_length, d.goal_area_width, s);
    }
    addBox(hl, side, d.penalty_area_length, d.penalty_area_width, s);
  }

  field.arcs.push_back(Arc2{Eigen::Vector2d::Zero(), 0.5 * d.center_circle_diameter, 0.0,
                            2.0 * M_PI});
  if (d.corner_arc_radius > 0.0) {
    // Quarter circles inside the field around each corner, counter-clockwise.
    const double r = d.corner_arc_radius;
    field.arcs.push_back(Arc2{Eigen::Vector2d(hl, hw), r, M_PI, 0.5 * M_PI});
    field.arcs.push_back(Arc2{Eigen::Vector2d(-hl, hw), r, -0.5 * M_PI, 0.5 * M_PI});
    field.arcs.push_back(Arc2{Eigen::Vector2d(-hl, -hw), r, 0.0, 0.5 * M_PI});
    field.arcs.push_back(Arc2{Eigen::Vector2d(hl, -hw), r, 0.5 * M_PI, 0.5 * M_PI});
  }

  const double mark_x = hl - d.penalty_mark_distance;
  for (double x : {0.0, -mark_x, mark_x}) {
    field.marks.push_back(Mark{Eigen::Vector2d(x, 0.0), d.penalty_mark_size, d.penalty_mark_shape});
  }
  for (double side : {-1.0, 1.0}) {
    field.goals.push_back(Goal{Eigen::Vector2d(side * hl, 0.0), d.goal_inner_width,
                               d.goal_post_diameter, d.goal_height, d.goal_depth});
  }
  return field;
}

std::vector<std::string> standardFieldNames() { return {"spl", "spl2019", "kid", "adult", "msl"}; }

FieldDimensions standardFieldDimensions(const std::string& name) {
  FieldDimensions spl;  // the defaults are the SPL 2020+ field
  if (name == "spl") return withName(spl, "SPL 2020");
  if (name == "spl2019") {
    FieldDimensions d = withName(spl, "SPL 2019");
    d.goal_area_length = 0.0;
    d.goal_area_width = 0.0;
    d.penalty_area_length = 0.6;
    d.penalty_area_width = 2.2;
    return d;
  }
  if (name == "kid" || name == "adult") {
    const bool kid = name == "kid";
    FieldDimensions d = withName(spl, kid ? "Humanoid KidSize" : "Humanoid AdultSize");
    d.length = kid ? 9.0 : 14.0;
    d.width = kid ? 6.0 : 9.0;
    d.goal_area_length = 1.0;
    d.goal_area_width = kid ? 3.0 : 4.0;
    d.penalty_area_length = kid ? 2.0 : 3.0;
    d.penalty_area_width = kid ? 5.0 : 6.0;
    d.penalty_mark_distance = kid ? 1.5 : 2.1;
    d.center_circle_diameter = kid ? 1.5 : 3.0;
    d.border_strip_width = 1.0;
    d.goal_inner_width = 2.6;
    d.goal_height = kid ? 1.2 : 1.8;
    d.goal_depth = 0.6;
    return d;
  }
  if (name == "msl") {
    FieldDimensions d = withName(spl, "Middle Size League");
    d.length = 22.0;
    d.width = 14.0;
    d.line_width = 0.125;
    d.goal_area_length = 0.75;
    d.goal_area_width = 3.9;
    d.penalty_area_length = 2.25;
    d.penalty_area_width = 6.9;
    d.penalty_mark_distance = 3.6;
    d.penalty_mark_size = 0.15;
    d.penalty_mark_shape = MarkShape::kDot;
    d.center_circle_diameter = 4.0;
    d.border_strip_width = 1.0;
    d.corner_arc_radius = 0.75;
    d.goal_inner_width = 2.0;
    d.goal_post_diameter = 0.125;
    d.goal_height = 1.0;
    d.goal_depth = 0.6;
    return d;
  }
  throw std::invalid_argument("unknown standard field '" + name +
                              "' (known: spl, spl2019, kid, adult, msl)");
}

FieldModel makeStandardField(const std::string& name) {
  return makeField(standardFieldDimensions(name));
}

}  // namespace houghloc
