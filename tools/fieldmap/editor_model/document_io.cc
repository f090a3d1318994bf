#include "tools/fieldmap/editor_model/document_io.h"

#include <fstream>
#include <optional>

#include "field_models/field_yaml.h"
#include "field_models/spl_import.h"

namespace houghloc::fieldmap {
namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// The rules dimensions a map was made from, when it is exactly makeField() of some dimensions
/// (read back from the lines makeField draws, in its order, then checked by regenerating).
std::optional<FieldDimensions> inferRules(const FieldModel& f) {
  const bool goal_area = f.segments.size() == 17;
  if (!(goal_area || f.segments.size() == 11) || f.marks.size() != 3 || f.goals.size() != 2 ||
      !(f.arcs.size() == 1 || f.arcs.size() == 5))
    return std::nullopt;
  FieldDimensions d;
  d.name = f.name;
  d.length = f.field_length;
  d.width = f.field_width;
  d.line_width = f.line_width;
  d.border_strip_width = f.border_strip_width;
  const double hl = 0.5 * d.length;
  // Each box starts with its front line (front_x, -w/2) -> (front_x, w/2), own side first.
  const Segment2& first_box = f.segments[5];
  const Segment2& penalty = f.segments[goal_area ? 8 : 5];
  d.goal_area_length = goal_area ? hl + first_box.a.x() : 0.0;
  d.goal_area_width = goal_area ? 2.0 * first_box.b.y() : 0.0;
  d.penalty_area_length = hl + penalty.a.x();
  d.penalty_area_width = 2.0 * penalty.b.y();
  d.center_circle_diameter = 2.0 * f.arcs[0].radius;
  d.corner_arc_radius = f.arcs.size() == 5 ? f.arcs[1].radius : 0.0;
  d.penalty_mark_distance = hl - f.marks[2].center.x();
  d.penalty_mark_size = f.marks[0].size;
  d.penalty_mark_shape = f.marks[0].shape;
  const Goal& g = f.goals[0];
  d.goal_inner_width = g.inner_width;
  d.goal_post_diameter = g.post_diameter;
  d.goal_height = g.height;
  d.goal_depth = g.depth;
  if (!sameField(makeField(d), f, 1e-9)) return std::nullopt;
  return d;
}

}  // namespace

EditorDocument loadDocument(const std::string& path) {
  if (endsWith(path, ".json")) {
    const FieldDimensions dims = readSplFieldDimensions(path);
    return EditorDocument(makeField(dims), dims);
  }
  FieldModel field = readFieldYaml(path);
  std::optional<FieldDimensions> rules = inferRules(field);
  return EditorDocument(std::move(field), std::move(rules));
}

EditorDocument standardDocument(const std::string& name) {
  const FieldDimensions dims = standardFieldDimensions(name);
  return EditorDocument(makeField(dims), dims);
}

void saveDocument(const EditorDocument& doc, const std::string& path) {
  writeFieldYaml(doc.field(), path);
}

void exportSplJson(const EditorDocument& doc, const std::string& path) {
  if (!doc.isRulesShaped()) {
    throw FormatError(path +
                      ": the map is not a rules-shaped field (edited by hand since it was "
                      "generated from dimensions); field_dimensions.json cannot describe it");
  }
  const std::string text = splFieldDimensionsToJson(*doc.rules());
  std::ofstream out(path, std::ios::binary);
  if (!(out << text)) throw FormatError(path + ": cannot write");
}

}  // namespace houghloc::fieldmap
