#pragma once

#include <QListWidget>
#include <QMainWindow>
#include <QUndoStack>
#include <vector>

#include "tools/fieldmap/editor/check_panel.h"
#include "tools/fieldmap/editor/field_view.h"
#include "tools/fieldmap/editor/number_form.h"
#include "tools/fieldmap/editor_model/snapping.h"
#include "tools/fieldmap/editor_model/symmetry.h"

class QLabel;
class QLineEdit;
class QDockWidget;

namespace houghloc::fieldmap {

/// `houghloc-fieldmap edit`: the map in a FieldView, the dimensions, property and validation
/// panels, and a QUndoStack of the model's Edits.
class EditorWindow : public QMainWindow {
 public:
  explicit EditorWindow(EditorDocument doc, QString path = {}, QWidget* parent = nullptr);

  const EditorDocument& document() const { return doc_; }
  const std::vector<FeatureId>& selection() const { return selection_; }
  FieldView* view() const { return view_; }
  QUndoStack* undoStack() const { return undo_; }
  QListWidget* validationList() const { return issues_; }
  CheckPanel* checkPanel() const { return check_; }
  /// Opens a recorded folder in the check panel and brings the panel to the front.
  void openCheck(const QString& folder, int frame);

  /// Applies an edit through the undo stack (every change to the map goes here).
  void apply(const Edit& edit);
  /// Replaces the document without undo (used by the undo commands themselves).
  void setDocument(const EditorDocument& doc);
  void select(std::vector<FeatureId> features);
  /// Writes the YAML map; false (and a message box unless quiet) on failure.
  bool saveTo(const QString& path, bool quiet = false);

  SnapConfig snap_config;

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void buildMenus();
  void buildPanels();
  void refresh();
  void redraw();  ///< the view and the check overlay
  void refreshProperties();
  bool save();
  bool saveAs();
  void open();
  void exportJson();
  void mirrorSelection(Mirror mirror);
  void addAtCentre(EditorKind kind);
  void updateTitle();

  EditorDocument doc_;
  QString path_;
  std::vector<FeatureId> selection_;
  FieldView* view_;
  QUndoStack* undo_;
  QListWidget* issues_ = nullptr;
  std::vector<FeatureId> issue_features_;  ///< per row of issues_; id -1 when map-wide
  QLineEdit* name_ = nullptr;              ///< the map's name (Dimensions panel)
  NumberForm* dimensions_ = nullptr;
  NumberForm* properties_ = nullptr;
  QLabel* property_title_ = nullptr;
  CheckPanel* check_ = nullptr;
  QDockWidget* check_dock_ = nullptr;
};

}  // namespace houghloc::fieldmap
