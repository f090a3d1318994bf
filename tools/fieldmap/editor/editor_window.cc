#include "tools/fieldmap/editor/editor_window.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QVBoxLayout>
#include <algorithm>

#include "tools/fieldmap/editor/feature_values.h"
#include "tools/fieldmap/editor_model/document_io.h"
#include "tools/fieldmap/editor_model/document_validation.h"

namespace houghloc::fieldmap {
namespace {

/// One model Edit on the QUndoStack: redo shows edit.after, undo edit.before.
class DocumentCommand : public QUndoCommand {
 public:
  DocumentCommand(EditorWindow* window, Edit edit)
      : QUndoCommand(QString::fromStdString(edit.text)), window_(window), edit_(std::move(edit)) {}
  void redo() override { window_->setDocument(edit_.after); }
  void undo() override { window_->setDocument(edit_.before); }

 private:
  EditorWindow* window_;
  Edit edit_;
};

/// The fixed end of what is being dragged, for parallel/perpendicular snapping.
std::optional<Eigen::Vector2d> anchorOf(const EditorDocument& doc, const FeatureId& f, Handle h) {
  if (f.kind != EditorKind::kSegment) return std::nullopt;
  return h == Handle::kEnd ? doc.segment(f).a : doc.segment(f).b;
}

}  // namespace

EditorWindow::EditorWindow(EditorDocument doc, QString path, QWidget* parent)
    : QMainWindow(parent),
      doc_(std::move(doc)),
      path_(std::move(path)),
      view_(new FieldView(this)),
      undo_(new QUndoStack(this)) {
  setCentralWidget(view_);
  view_->on_selection = [this](std::vector<FeatureId> s) { select(std::move(s)); };
  view_->on_handle_dragged = [this](FeatureId f, Handle h, Eigen::Vector2d p) {
    apply(moveHandle(doc_, f, h, p));
  };
  view_->on_selection_moved = [this](Eigen::Vector2d delta) {
    if (snap_config.enabled && snap_config.grid_m > 0.0)
      delta = (delta / snap_config.grid_m).array().round().matrix() * snap_config.grid_m;
    if (!delta.isZero()) apply(translateFeatures(doc_, selection_, delta));
  };
  view_->snap = [this](FeatureId f, Handle h, Eigen::Vector2d p) {
    if (h == Handle::kRadius || h == Handle::kArcStart || h == Handle::kArcEnd) return p;
    return snapPoint(doc_, p, f, anchorOf(doc_, f, h), snap_config).point;
  };
  connect(undo_, &QUndoStack::cleanChanged, this, [this] { updateTitle(); });
  buildMenus();
  buildPanels();
  resize(1280, 800);
  refresh();
  view_->fitField();
}

void EditorWindow::apply(const Edit& edit) { undo_->push(new DocumentCommand(this, edit)); }

void EditorWindow::setDocument(const EditorDocument& doc) {
  doc_ = doc;
  selection_.erase(std::remove_if(selection_.begin(), selection_.end(),
                                  [&](const FeatureId& f) { return !doc_.contains(f); }),
                   selection_.end());
  refresh();
}

void EditorWindow::openCheck(const QString& folder, int frame) {
  check_->openRecording(folder, frame);
  check_dock_->raise();
}

void EditorWindow::select(std::vector<FeatureId> features) {
  selection_ = std::move(features);
  redraw();
  refreshProperties();
}

void EditorWindow::redraw() {
  view_->showDocument(doc_, selection_);
  check_->update(doc_);
}

void EditorWindow::refresh() {
  redraw();
  dimensions_->setValues(dimensionValues(dimensionsOf(doc_)));
  name_->setText(QString::fromStdString(doc_.field().name));
  issues_->clear();
  issue_features_.clear();
  const std::vector<DocumentIssue> issues = validateDocument(doc_);
  for (const DocumentIssue& issue : issues) {
    issues_->addItem(QString::fromStdString(issue.text));
    issue_features_.push_back(issue.feature.value_or(FeatureId{EditorKind::kSegment, -1}));
  }
  if (issues.empty()) issues_->addItem("map is valid");
  refreshProperties();
  updateTitle();
  statusBar()->showMessage(
      QString::fromStdString((doc_.isRulesShaped() ? "rules-shaped, " : "") +
                             std::to_string(doc_.field().segments.size()) + " segments, " +
                             std::to_string(doc_.field().arcs.size()) + " arcs, " +
                             std::to_string(doc_.field().marks.size()) + " marks, " +
                             std::to_string(doc_.field().goals.size()) + " goals"));
}

void EditorWindow::refreshProperties() {
  if (selection_.size() != 1) {
    property_title_->setText(selection_.empty()
                                 ? "nothing selected"
                                 : QString("%1 features selected").arg(selection_.size()));
    properties_->setFields({});
    return;
  }
  const FeatureId f = selection_.front();
  property_title_->setText(QString::fromStdString(describeFeatureId(f)));
  properties_->setFields(featureLabels(f.kind));
  properties_->setValues(featureValues(doc_, f));
}

void EditorWindow::updateTitle() {
  const QString name = path_.isEmpty() ? "untitled" : path_;
  setWindowTitle(QString("%1%2 - houghloc-fieldmap edit").arg(name, undo_->isClean() ? "" : " *"));
}

bool EditorWindow::saveTo(const QString& path, bool quiet) {
  try {
    saveDocument(doc_, path.toStdString());
  } catch (const std::exception& e) {
    if (!quiet) QMessageBox::critical(this, "Save failed", e.what());
    return false;
  }
  path_ = path;
  undo_->setClean();
  updateTitle();
  return true;
}

bool EditorWindow::save() {
  return path_.isEmpty() || path_.endsWith(".json") ? saveAs() : saveTo(path_);
}

bool EditorWindow::saveAs() {
  const QString path = QFileDialog::getSaveFileName(this, "Save map", path_, "YAML maps (*.yaml)");
  return !path.isEmpty() && saveTo(path);
}

void EditorWindow::open() {
  const QString path = QFileDialog::getOpenFileName(this, "Open map", {},
                                                    "Maps (*.yaml *.yml *.json);;All files (*)");
  if (path.isEmpty()) return;
  try {
    apply(Edit{"Open " + path.toStdString(), doc_, loadDocument(path.toStdString())});
  } catch (const std::exception& e) {
    QMessageBox::critical(this, "Open failed", e.what());
  }
}

void EditorWindow::exportJson() {
  const QString path = QFileDialog::getSaveFileName(this, "Export field_dimensions.json",
                                                    "field_dimensions.json", "JSON (*.json)");
  if (path.isEmpty()) return;
  try {
    exportSplJson(doc_, path.toStdString());
  } catch (const std::exception& e) {
    QMessageBox::critical(this, "Export failed", e.what());
  }
}

void EditorWindow::mirrorSelection(Mirror mirror) {
  if (!selection_.empty()) apply(mirrorFeatures(doc_, selection_, mirror));
}

void EditorWindow::addAtCentre(EditorKind kind) {
  const Eigen::Vector2d c = toField(view_->mapToScene(view_->viewport()->rect().center()));
  const Eigen::Vector2d p = snapPoint(doc_, c, std::nullopt, std::nullopt, snap_config).point;
  switch (kind) {
    case EditorKind::kSegment:
      apply(addSegment(doc_, Segment2{p, p + Eigen::Vector2d(1, 0)}));
      break;
    case EditorKind::kArc:
      apply(addArc(doc_, Arc2{p, 0.5, 0.0, M_PI / 2}));
      break;
    case EditorKind::kMark:
      apply(addMark(doc_, Mark{p, 0.1, MarkShape::kCross}));
      break;
    case EditorKind::kGoal:
      apply(addGoal(doc_, Goal{p}));
      break;
  }
  select({{kind, doc_.ids(kind).back()}});
}

void EditorWindow::closeEvent(QCloseEvent* event) {
  if (undo_->isClean()) return event->accept();
  const auto answer = QMessageBox::question(
      this, "Unsaved changes", "The map has unsaved changes. Save them before quitting?",
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  if (answer == QMessageBox::Discard || (answer == QMessageBox::Save && save())) {
    event->accept();
  } else {
    event->ignore();
  }
}

}  // namespace houghloc::fieldmap
