#pragma once

#include <optional>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/standard_fields.h"

namespace houghloc::fieldmap {

/// The kinds of map entry the editor edits: the three line-feature kinds and goals.
enum class EditorKind { kSegment = 0, kArc = 1, kMark = 2, kGoal = 3 };

/// A map entry by a stable id: ids survive edits, undo and the deletion of other entries, unlike
/// the indices into FieldModel's lists.
struct FeatureId {
  EditorKind kind = EditorKind::kSegment;
  int id = -1;

  bool operator==(const FeatureId& o) const { return kind == o.kind && id == o.id; }
  bool operator!=(const FeatureId& o) const { return !(*this == o); }
  bool operator<(const FeatureId& o) const { return kind != o.kind ? kind < o.kind : id < o.id; }
};

/// "segment 3", "arc 0", ... for menus and messages.
std::string describeFeatureId(const FeatureId& feature);

/// The map being edited: a FieldModel plus one stable id per entry, and the rules dimensions it
/// was generated from (standard field, SPL JSON or the dimensions panel), if any. A value type:
/// edits produce a new document, undo restores an old one.
class EditorDocument {
 public:
  EditorDocument() = default;
  /// Every entry of `field` gets a fresh id; `rules` are the dimensions it was made from.
  explicit EditorDocument(FieldModel field, std::optional<FieldDimensions> rules = std::nullopt);

  const FieldModel& field() const { return field_; }
  /// The dimensions the layout was generated from (kept after free edits, for the panel).
  const std::optional<FieldDimensions>& rules() const { return rules_; }
  /// True when the map is exactly makeField(rules()): no free edit since the generation.
  bool isRulesShaped() const;

  /// Ids of every entry of one kind, in FieldModel order.
  const std::vector<int>& ids(EditorKind kind) const { return ids_[static_cast<int>(kind)]; }
  std::vector<FeatureId> allFeatures() const;
  /// Index into the FieldModel list of the feature's kind; -1 when it is not in the document.
  int indexOf(const FeatureId& feature) const;
  bool contains(const FeatureId& feature) const { return indexOf(feature) >= 0; }
  FeatureId idAt(EditorKind kind, int index) const { return {kind, ids(kind).at(index)}; }

  /// Writable entries; the caller must keep the id lists in step (use add/remove to change sizes).
  Segment2& segment(const FeatureId& f) { return field_.segments.at(checkedIndex(f)); }
  Arc2& arc(const FeatureId& f) { return field_.arcs.at(checkedIndex(f)); }
  Mark& mark(const FeatureId& f) { return field_.marks.at(checkedIndex(f)); }
  Goal& goal(const FeatureId& f) { return field_.goals.at(checkedIndex(f)); }
  const Segment2& segment(const FeatureId& f) const { return field_.segments.at(checkedIndex(f)); }
  const Arc2& arc(const FeatureId& f) const { return field_.arcs.at(checkedIndex(f)); }
  const Mark& mark(const FeatureId& f) const { return field_.marks.at(checkedIndex(f)); }
  const Goal& goal(const FeatureId& f) const { return field_.goals.at(checkedIndex(f)); }

  FeatureId add(const Segment2& s);
  FeatureId add(const Arc2& a);
  FeatureId add(const Mark& m);
  FeatureId add(const Goal& g);
  /// Removes the entry; throws std::out_of_range when it is not in the document.
  void remove(const FeatureId& feature);

  /// Name, length, width, line width and border strip (the scalar part of the map).
  FieldModel& header() { return field_; }

 private:
  int checkedIndex(const FeatureId& feature) const;
  FeatureId addId(EditorKind kind);

  FieldModel field_;
  std::optional<FieldDimensions> rules_;
  std::vector<int> ids_[4];
  int next_id_ = 0;
};

/// True when both maps have the same header and the same entries within `tolerance_m`.
bool sameField(const FieldModel& a, const FieldModel& b, double tolerance_m = 1e-9);

}  // namespace houghloc::fieldmap
