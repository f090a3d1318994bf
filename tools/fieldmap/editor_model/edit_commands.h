#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "tools/fieldmap/editor_model/editor_document.h"

namespace houghloc::fieldmap {

/// One undoable edit: the document before and after it. Whole-document snapshots keep undo exact
/// (ids included) and every command trivially invertible; a map has a few dozen entries, so a
/// snapshot is a few kB.
struct Edit {
  std::string text;  ///< for the undo menu, e.g. "Move endpoint of segment 4"
  EditorDocument before;
  EditorDocument after;
};

/// Undo/redo of Edits without Qt (the editor wraps each Edit in a QUndoCommand instead).
class EditHistory {
 public:
  /// Applies `edit` (document = edit.after) and drops the redo list.
  void push(Edit edit, EditorDocument& document);
  bool undo(EditorDocument& document);  ///< false when there is nothing to undo
  bool redo(EditorDocument& document);  ///< false when there is nothing to redo
  bool canUndo() const { return !done_.empty(); }
  bool canRedo() const { return !undone_.empty(); }

 private:
  std::vector<Edit> done_;
  std::vector<Edit> undone_;
};

/// Where a point of a feature sits, for dragging handles.
enum class Handle {
  kStart,     ///< segment a
  kEnd,       ///< segment b
  kCenter,    ///< arc, mark or goal centre
  kRadius,    ///< arc: a point on the circle sets the radius
  kArcStart,  ///< arc: a point sets the start angle (the end stays)
  kArcEnd,    ///< arc: a point sets the end angle (the start stays)
};

/// Edits: each returns the Edit from `doc` to the changed document, or throws std::out_of_range
/// for a feature that is not in `doc`. Angles are normalized to DESIGN §4's ranges.
Edit moveHandle(const EditorDocument& doc, const FeatureId& feature, Handle handle,
                const Eigen::Vector2d& point);
Edit setSegment(const EditorDocument& doc, const FeatureId& feature, const Segment2& value);
Edit setArc(const EditorDocument& doc, const FeatureId& feature, const Arc2& value);
Edit setMark(const EditorDocument& doc, const FeatureId& feature, const Mark& value);
Edit setGoal(const EditorDocument& doc, const FeatureId& feature, const Goal& value);
/// Adds one entry; the new id is the last of its kind in edit.after.
Edit addSegment(const EditorDocument& doc, const Segment2& value);
Edit addArc(const EditorDocument& doc, const Arc2& value);
Edit addMark(const EditorDocument& doc, const Mark& value);
Edit addGoal(const EditorDocument& doc, const Goal& value);
Edit deleteFeatures(const EditorDocument& doc, const std::vector<FeatureId>& features);
/// Moves every listed feature by `delta_m`.
Edit translateFeatures(const EditorDocument& doc, const std::vector<FeatureId>& features,
                       const Eigen::Vector2d& delta_m);
/// New name, length, width, line width or border strip; the lines stay where they are.
Edit setHeader(const EditorDocument& doc, const FieldModel& header);
/// Replaces the whole map by makeField(dims) (fresh ids): the dimensions panel.
Edit regenerate(const EditorDocument& doc, const FieldDimensions& dims);

/// (-pi, pi] for any finite angle.
double normalizeAngle(double angle_rad);

}  // namespace houghloc::fieldmap
