#pragma once

#include <QGraphicsView>
#include <functional>
#include <optional>
#include <vector>

#include "tools/fieldmap/editor_model/edit_commands.h"

namespace houghloc::fieldmap {

/// Scene coordinates are field metres with y flipped (Qt's y points down), so the view shows the
/// field frame of DESIGN §3: x to the right (opponent goal), y up.
QPointF toScene(const Eigen::Vector2d& field_m);
Eigen::Vector2d toField(const QPointF& scene);

/// Top view of a document: carpet, metric grid and axes, lines at their painted width, goals;
/// handles on the selected features. Mouse: left click selects (Ctrl adds), left drag on a handle
/// moves that handle, on a selected feature moves the selection; wheel zooms to the cursor;
/// middle or right drag pans. Edits are reported through the callbacks, never applied here.
class FieldView : public QGraphicsView {
 public:
  explicit FieldView(QWidget* parent = nullptr);

  /// Redraws everything from `doc` with `selection` highlighted.
  void showDocument(const EditorDocument& doc, const std::vector<FeatureId>& selection);
  /// Fits the carpet into the window.
  void fitField();
  /// Extra items drawn over the map (e.g. a frame's line points); owned by the scene.
  QGraphicsItemGroup* overlay() const { return overlay_; }

  std::function<void(std::vector<FeatureId>)> on_selection;
  std::function<void(FeatureId, Handle, Eigen::Vector2d)> on_handle_dragged;
  std::function<void(Eigen::Vector2d)> on_selection_moved;
  /// Shift+drag: the check pose moves by this field-frame translation; Shift+wheel turns it.
  std::function<void(Eigen::Vector2d)> on_pose_dragged;
  std::function<void(double)> on_pose_turned;
  /// Where a dragged handle lands (snapping); the identity when unset.
  std::function<Eigen::Vector2d(FeatureId, Handle, Eigen::Vector2d)> snap;

 protected:
  void drawBackground(QPainter* painter, const QRectF& rect) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  struct Drag {
    std::optional<FeatureId> feature;  ///< set: a handle drag
    Handle handle = Handle::kCenter;
    QPointF start_scene;
    QGraphicsItem* item = nullptr;  ///< the handle being moved, for feedback
    bool moved = false;
    bool pose = false;  ///< Shift: drags the check pose, not the map
  };
  void addFeatureItems(const EditorDocument& doc, const FeatureId& f, bool selected);
  void addHandles(const EditorDocument& doc, const FeatureId& f);

  FieldModel field_;  ///< header for the background
  std::vector<FeatureId> selection_;
  QGraphicsItemGroup* overlay_ = nullptr;
  std::optional<Drag> drag_;
  std::optional<QPoint> pan_from_;
};

}  // namespace houghloc::fieldmap
