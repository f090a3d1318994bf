#include "tools/fieldmap/editor/feature_values.h"

#include <cmath>

#include "field_models/angles.h"

namespace houghloc::fieldmap {
namespace {

/// FieldDimensions members in panel order.
const std::pair<const char*, double FieldDimensions::*> kDimensions[] = {
    {"length (m)", &FieldDimensions::length},
    {"width (m)", &FieldDimensions::width},
    {"line width (m)", &FieldDimensions::line_width},
    {"border strip (m)", &FieldDimensions::border_strip_width},
    {"goal area length (m)", &FieldDimensions::goal_area_length},
    {"goal area width (m)", &FieldDimensions::goal_area_width},
    {"penalty area length (m)", &FieldDimensions::penalty_area_length},
    {"penalty area width (m)", &FieldDimensions::penalty_area_width},
    {"penalty mark distance (m)", &FieldDimensions::penalty_mark_distance},
    {"penalty mark size (m)", &FieldDimensions::penalty_mark_size},
    {"centre circle diameter (m)", &FieldDimensions::center_circle_diameter},
    {"corner arc radius (m)", &FieldDimensions::corner_arc_radius},
    {"goal inner width (m)", &FieldDimensions::goal_inner_width},
    {"goal depth (m)", &FieldDimensions::goal_depth},
};

}  // namespace

std::vector<QString> featureLabels(EditorKind kind) {
  switch (kind) {
    case EditorKind::kSegment:
      return {"a x (m)", "a y (m)", "b x (m)", "b y (m)"};
    case EditorKind::kArc:
      return {"centre x (m)", "centre y (m)", "radius (m)", "start (deg)", "sweep (deg)"};
    case EditorKind::kMark:
      return {"centre x (m)", "centre y (m)", "size (m)", "dot (0/1)"};
    case EditorKind::kGoal:
      return {"centre x (m)",      "centre y (m)", "inner width (m)",
              "post diameter (m)", "height (m)",   "depth (m)"};
  }
  return {};
}

std::vector<double> featureValues(const EditorDocument& doc, const FeatureId& f) {
  switch (f.kind) {
    case EditorKind::kSegment: {
      const Segment2& s = doc.segment(f);
      return {s.a.x(), s.a.y(), s.b.x(), s.b.y()};
    }
    case EditorKind::kArc: {
      const Arc2& a = doc.arc(f);
      return {a.center.x(), a.center.y(), a.radius, a.start_rad / kDeg, a.sweep_rad / kDeg};
    }
    case EditorKind::kMark: {
      const Mark& m = doc.mark(f);
      return {m.center.x(), m.center.y(), m.size, m.shape == MarkShape::kDot ? 1.0 : 0.0};
    }
    case EditorKind::kGoal: {
      const Goal& g = doc.goal(f);
      return {g.center.x(), g.center.y(), g.inner_width, g.post_diameter, g.height, g.depth};
    }
  }
  return {};
}

Edit setFeatureValues(const EditorDocument& doc, const FeatureId& f, const std::vector<double>& v) {
  const Eigen::Vector2d c(v.at(0), v.at(1));
  switch (f.kind) {
    case EditorKind::kSegment:
      return setSegment(doc, f, Segment2{c, {v.at(2), v.at(3)}});
    case EditorKind::kArc:
      return setArc(doc, f, Arc2{c, v.at(2), v.at(3) * kDeg, v.at(4) * kDeg});
    case EditorKind::kMark:
      return setMark(doc, f,
                     Mark{c, v.at(2), v.at(3) >= 0.5 ? MarkShape::kDot : MarkShape::kCross});
    case EditorKind::kGoal:
      return setGoal(doc, f, Goal{c, v.at(2), v.at(3), v.at(4), v.at(5)});
  }
  return Edit{"", doc, doc};
}

std::vector<QString> dimensionLabels() {
  std::vector<QString> out;
  for (const auto& [label, member] : kDimensions) out.push_back(label);
  return out;
}

std::vector<double> dimensionValues(const FieldDimensions& dims) {
  std::vector<double> out;
  for (const auto& [label, member] : kDimensions) out.push_back(dims.*member);
  return out;
}

FieldDimensions dimensionsFrom(FieldDimensions base, const std::vector<double>& values) {
  std::size_t i = 0;
  for (const auto& [label, member] : kDimensions) base.*member = values.at(i++);
  return base;
}

FieldDimensions dimensionsOf(const EditorDocument& doc) {
  FieldDimensions dims = doc.rules().value_or(FieldDimensions{});
  const FieldModel& f = doc.field();
  dims.name = f.name;
  dims.length = f.field_length;
  dims.width = f.field_width;
  dims.line_width = f.line_width;
  dims.border_strip_width = f.border_strip_width;
  return dims;
}

}  // namespace houghloc::fieldmap
