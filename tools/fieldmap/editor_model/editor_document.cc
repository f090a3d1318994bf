#include "tools/fieldmap/editor_model/editor_document.h"

#include <algorithm>
#include <stdexcept>

namespace houghloc::fieldmap {
namespace {

bool near(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double tol) {
  return (a - b).cwiseAbs().maxCoeff() <= tol;
}
bool near(double a, double b, double tol) { return std::abs(a - b) <= tol; }

template <typename T, typename Same>
bool sameLists(const std::vector<T>& a, const std::vector<T>& b, Same same) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same(a[i], b[i])) return false;
  return true;
}

}  // namespace

std::string describeFeatureId(const FeatureId& feature) {
  static const char* kNames[] = {"segment", "arc", "mark", "goal"};
  return std::string(kNames[static_cast<int>(feature.kind)]) + " " + std::to_string(feature.id);
}

EditorDocument::EditorDocument(FieldModel field, std::optional<FieldDimensions> rules)
    : field_(std::move(field)), rules_(std::move(rules)) {
  auto fill = [&](EditorKind kind, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) addId(kind);
  };
  fill(EditorKind::kSegment, field_.segments.size());
  fill(EditorKind::kArc, field_.arcs.size());
  fill(EditorKind::kMark, field_.marks.size());
  fill(EditorKind::kGoal, field_.goals.size());
}

bool EditorDocument::isRulesShaped() const {
  return rules_.has_value() && sameField(makeField(*rules_), field_);
}

std::vector<FeatureId> EditorDocument::allFeatures() const {
  std::vector<FeatureId> out;
  for (int k = 0; k < 4; ++k)
    for (int id : ids_[k]) out.push_back({static_cast<EditorKind>(k), id});
  return out;
}

int EditorDocument::indexOf(const FeatureId& feature) const {
  const std::vector<int>& list = ids(feature.kind);
  const auto it = std::find(list.begin(), list.end(), feature.id);
  return it == list.end() ? -1 : static_cast<int>(it - list.begin());
}

int EditorDocument::checkedIndex(const FeatureId& feature) const {
  const int index = indexOf(feature);
  if (index < 0) throw std::out_of_range("no " + describeFeatureId(feature) + " in the map");
  return index;
}

FeatureId EditorDocument::addId(EditorKind kind) {
  ids_[static_cast<int>(kind)].push_back(next_id_);
  return {kind, next_id_++};
}

FeatureId EditorDocument::add(const Segment2& s) {
  field_.segments.push_back(s);
  return addId(EditorKind::kSegment);
}
FeatureId EditorDocument::add(const Arc2& a) {
  field_.arcs.push_back(a);
  return addId(EditorKind::kArc);
}
FeatureId EditorDocument::add(const Mark& m) {
  field_.marks.push_back(m);
  return addId(EditorKind::kMark);
}
FeatureId EditorDocument::add(const Goal& g) {
  field_.goals.push_back(g);
  return addId(EditorKind::kGoal);
}

void EditorDocument::remove(const FeatureId& feature) {
  const int index = checkedIndex(feature);
  std::vector<int>& list = ids_[static_cast<int>(feature.kind)];
  list.erase(list.begin() + index);
  switch (feature.kind) {
    case EditorKind::kSegment:
      field_.segments.erase(field_.segments.begin() + index);
      break;
    case EditorKind::kArc:
      field_.arcs.erase(field_.arcs.begin() + index);
      break;
    case EditorKind::kMark:
      field_.marks.erase(field_.marks.begin() + index);
      break;
    case EditorKind::kGoal:
      field_.goals.erase(field_.goals.begin() + index);
      break;
  }
}

bool sameField(const FieldModel& a, const FieldModel& b, double tol) {
  if (a.name != b.name || !near(a.field_length, b.field_length, tol) ||
      !near(a.field_width, b.field_width, tol) || !near(a.line_width, b.line_width, tol) ||
      !near(a.border_strip_width, b.border_strip_width, tol))
    return false;
  return sameLists(a.segments, b.segments,
                   [&](const Segment2& s, const Segment2& t) {
                     return near(s.a, t.a, tol) && near(s.b, t.b, tol);
                   }) &&
         sameLists(a.arcs, b.arcs,
                   [&](const Arc2& s, const Arc2& t) {
                     return near(s.center, t.center, tol) && near(s.radius, t.radius, tol) &&
                            near(s.start_rad, t.start_rad, tol) &&
                            near(s.sweep_rad, t.sweep_rad, tol);
                   }) &&
         sameLists(a.marks, b.marks,
                   [&](const Mark& s, const Mark& t) {
                     return near(s.center, t.center, tol) && near(s.size, t.size, tol) &&
                            s.shape == t.shape;
                   }) &&
         sameLists(a.goals, b.goals, [&](const Goal& s, const Goal& t) {
           return near(s.center, t.center, tol) && near(s.inner_width, t.inner_width, tol) &&
                  near(s.post_diameter, t.post_diameter, tol) && near(s.height, t.height, tol) &&
                  near(s.depth, t.depth, tol);
         });
}

}  // namespace houghloc::fieldmap
