// EditorWindow's menus and dock panels.
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QPushButton>
#include <QVBoxLayout>

#include "tools/fieldmap/editor/editor_window.h"
#include "tools/fieldmap/editor/feature_values.h"

namespace houghloc::fieldmap {

void EditorWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu("&File");
  file->addAction(
      "&Open...", this, [this] { open(); }, QKeySequence::Open);
  file->addAction(
      "&Save", this, [this] { save(); }, QKeySequence::Save);
  file->addAction(
      "Save &as...", this, [this] { saveAs(); }, QKeySequence::SaveAs);
  file->addAction("&Export field_dimensions.json...", this, [this] { exportJson(); });
  file->addSeparator();
  file->addAction(
      "&Quit", this, [this] { close(); }, QKeySequence::Quit);

  QMenu* edit = menuBar()->addMenu("&Edit");
  QAction* undo = undo_->createUndoAction(this, "&Undo");
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = undo_->createRedoAction(this, "&Redo");
  redo->setShortcut(QKeySequence::Redo);
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  edit->addAction(
      "&Delete selection", this,
      [this] {
        if (!selection_.empty()) apply(deleteFeatures(doc_, selection_));
      },
      QKeySequence::Delete);
  edit->addAction("Add &segment", this, [this] { addAtCentre(EditorKind::kSegment); });
  edit->addAction("Add &arc", this, [this] { addAtCentre(EditorKind::kArc); });
  edit->addAction("Add &mark", this, [this] { addAtCentre(EditorKind::kMark); });
  edit->addAction("Add &goal", this, [this] { addAtCentre(EditorKind::kGoal); });
  edit->addSeparator();
  edit->addAction("Mirror through the &centre", this,
                  [this] { mirrorSelection(Mirror::kThroughCenter); });
  edit->addAction("Mirror across the &x axis", this,
                  [this] { mirrorSelection(Mirror::kAcrossXAxis); });
  edit->addAction("Mirror across the &y axis", this,
                  [this] { mirrorSelection(Mirror::kAcrossYAxis); });
  QAction* snapping = edit->addAction("S&nap to grid, endpoints and directions");
  snapping->setCheckable(true);
  snapping->setChecked(snap_config.enabled);
  connect(snapping, &QAction::toggled, this, [this](bool on) { snap_config.enabled = on; });

  QMenu* view = menuBar()->addMenu("&View");
  view->addAction("&Fit field", this, [this] { view_->fitField(); });
}

void EditorWindow::buildPanels() {
  auto* dims_widget = new QWidget;
  auto* dims_layout = new QVBoxLayout(dims_widget);
  dimensions_ = new NumberForm;
  dimensions_->setFields(dimensionLabels(), 3);
  // The name is part of the map, not of the layout: renaming is its own undoable edit.
  name_ = new QLineEdit;
  name_->setObjectName("map_name");
  dimensions_->layout()->insertRow(0, "name", name_);
  connect(name_, &QLineEdit::editingFinished, this, [this] {
    if (name_->text().toStdString() == doc_.field().name) return;
    FieldModel header = doc_.field();
    header.name = name_->text().toStdString();
    apply(setHeader(doc_, header));
  });
  auto* regenerate_button = new QPushButton("Regenerate rules layout");
  connect(regenerate_button, &QPushButton::clicked, this, [this] {
    FieldDimensions dims = dimensionsFrom(dimensionsOf(doc_), dimensions_->values());
    dims.name = name_->text().toStdString();
    apply(regenerate(doc_, dims));
  });
  dims_layout->addWidget(dimensions_);
  dims_layout->addWidget(regenerate_button);
  dims_layout->addStretch();
  auto* dims_dock = new QDockWidget("Dimensions", this);
  dims_dock->setObjectName("dimensions");
  dims_dock->setWidget(dims_widget);
  addDockWidget(Qt::LeftDockWidgetArea, dims_dock);

  auto* props_widget = new QWidget;
  auto* props_layout = new QVBoxLayout(props_widget);
  property_title_ = new QLabel;
  properties_ = new NumberForm;
  auto* apply_button = new QPushButton("Apply");
  connect(apply_button, &QPushButton::clicked, this, [this] {
    if (selection_.size() == 1) apply(setFeatureValues(doc_, selection_[0], properties_->values()));
  });
  props_layout->addWidget(property_title_);
  props_layout->addWidget(properties_);
  props_layout->addWidget(apply_button);
  props_layout->addStretch();
  auto* props_dock = new QDockWidget("Properties", this);
  props_dock->setObjectName("properties");
  props_dock->setWidget(props_widget);
  addDockWidget(Qt::RightDockWidgetArea, props_dock);

  check_ = new CheckPanel(view_);
  check_->on_feature_clicked = [this](FeatureId f) { select({f}); };
  view_->on_pose_dragged = [this](Eigen::Vector2d d) { check_->nudgePose(d, 0.0); };
  view_->on_pose_turned = [this](double rad) { check_->nudgePose(Eigen::Vector2d::Zero(), rad); };
  auto* check_dock = new QDockWidget("Check against a frame", this);
  check_dock->setObjectName("check");
  check_dock->setWidget(check_);
  addDockWidget(Qt::LeftDockWidgetArea, check_dock);
  tabifyDockWidget(dims_dock, check_dock);
  dims_dock->raise();
  check_dock_ = check_dock;

  issues_ = new QListWidget;
  connect(issues_, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
    const int row = issues_->row(item);
    if (row >= 0 && row < static_cast<int>(issue_features_.size()) && issue_features_[row].id >= 0)
      select({issue_features_[row]});
  });
  auto* issues_dock = new QDockWidget("Validation", this);
  issues_dock->setObjectName("validation");
  issues_dock->setWidget(issues_);
  addDockWidget(Qt::RightDockWidgetArea, issues_dock);
}

}  // namespace houghloc::fieldmap
