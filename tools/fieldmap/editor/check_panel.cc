#include "tools/fieldmap/editor/check_panel.h"

#include <QFileDialog>
#include <QGraphicsEllipseItem>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <utility>

#include "field_models/angles.h"
#include "field_models/field_distance.h"
#include "tools/fieldmap/editor/field_view.h"

namespace houghloc::fieldmap {
namespace {

QString centimetres(double m) { return QString::number(100.0 * m, 'f', 1); }

}  // namespace

CheckPanel::CheckPanel(FieldView* view, QWidget* parent)
    : QWidget(parent),
      view_(view),
      status_(new QLabel("no recording open")),
      frame_box_(new QSpinBox),
      located_status_(new QLabel),
      pose_(new NumberForm),
      table_(new QTableWidget(0, 4)) {
  auto* layout = new QVBoxLayout(this);
  auto* open = new QPushButton("Open recorded folder...");
  connect(open, &QPushButton::clicked, this, [this] {
    const QString folder = QFileDialog::getExistingDirectory(this, "Recorded folder");
    if (folder.isEmpty()) return;
    try {
      openRecording(folder);
    } catch (const std::exception& e) {
      QMessageBox::critical(this, "Cannot open the recording", e.what());
    }
  });
  status_->setWordWrap(true);
  frame_box_->setPrefix("frame ");
  frame_box_->setEnabled(false);
  connect(frame_box_, QOverload<int>::of(&QSpinBox::valueChanged), this,
          [this](int index) { showFrame(index); });
  pose_->setFields({"robot x (m)", "robot y (m)", "robot theta (deg)"}, 3);
  auto* apply_pose = new QPushButton("Apply pose");
  connect(apply_pose, &QPushButton::clicked, this, [this] { update(doc_); });
  auto* truth = new QPushButton("Ground truth pose");
  connect(truth, &QPushButton::clicked, this, [this] {
    if (frame_ && frame_->ground_truth) setPose(*frame_->ground_truth);
  });
  auto* localize_button = new QPushButton("Localize");
  localize_button->setObjectName("localize");
  localize_button->setToolTip(
      "The global localizer's pose for this frame on the map as edited; "
      "press again for the next pose");
  connect(localize_button, &QPushButton::clicked, this, [this] { localize(); });
  table_->setHorizontalHeaderLabels({"feature", "points", "mean cm", "p95 cm"});
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  connect(table_, &QTableWidget::cellClicked, this, [this](int row, int) {
    const int i = row - 1;  // row 0 is the overall line
    if (i < 0 || i >= static_cast<int>(report_.features.size()) || !on_feature_clicked) return;
    const FeatureRef ref = report_.features[i].feature;
    on_feature_clicked(doc_.idAt(static_cast<EditorKind>(ref.kind), ref.index));
  });
  layout->addWidget(open);
  layout->addWidget(status_);
  layout->addWidget(frame_box_);
  layout->addWidget(pose_);
  layout->addWidget(apply_pose);
  layout->addWidget(truth);
  layout->addWidget(localize_button);
  layout->addWidget(located_status_);
  layout->addWidget(new QLabel("Shift+drag in the view moves the pose, Shift+wheel turns it."));
  layout->addWidget(table_, 1);
}

void CheckPanel::openRecording(const QString& folder, int frame) {
  auto source = std::make_unique<FrameSource>(folder.toStdString());
  if (frame < 0 || frame >= source->frameCount()) {
    throw RecordingError(source->recording().folder + "/frames.csv: no frame " +
                         std::to_string(frame) + " (the folder has " +
                         std::to_string(source->frameCount()) + ")");
  }
  source_ = std::move(source);
  frame_box_->blockSignals(true);
  frame_box_->setRange(0, std::max(0, source_->frameCount() - 1));
  frame_box_->setValue(frame);
  frame_box_->blockSignals(false);
  frame_box_->setEnabled(true);
  showFrame(frame);
}

void CheckPanel::showFrame(int index) {
  if (!source_) return;
  located_.reset();
  located_status_->clear();
  try {
    frame_ = source_->frame(index);
  } catch (const std::exception& e) {
    frame_.reset();
    status_->setText(e.what());
    update(doc_);
    return;
  }
  status_->setText(QString("%1\nframe %2 of %3, %4 line points%5")
                       .arg(QString::fromStdString(source_->recording().folder))
                       .arg(index)
                       .arg(source_->frameCount())
                       .arg(frame_->points_robot.size())
                       .arg(frame_->ground_truth ? ", ground truth pose" : ", no ground truth"));
  setPose(frame_->ground_truth.value_or(pose()));
}

Pose2 CheckPanel::pose() const {
  const std::vector<double> v = pose_->values();
  return Pose2{v[0], v[1], v[2] * kDeg};
}

void CheckPanel::setPose(const Pose2& p) {
  pose_->setValues({p.x, p.y, p.theta / kDeg});
  update(doc_);
  if (on_pose_changed) on_pose_changed();
}

void CheckPanel::nudgePose(const Eigen::Vector2d& delta_m, double delta_rad) {
  if (!frame_) return;
  Pose2 p = pose();
  setPose(Pose2{p.x + delta_m.x(), p.y + delta_m.y(), p.theta + delta_rad});
}

void CheckPanel::localize() {
  if (!source_ || !frame_) return;
  if (!located_) {
    try {
      located_ = source_->frame(frame_->index, &doc_.field()).located;
      // Best first by the residual on this map: the localizer's own order is by Hough votes,
      // which can put a pose that slides 20 cm along a weakly constrained line first.
      std::vector<std::pair<double, Pose2>> ranked;
      for (const Pose2& p : *located_)
        ranked.push_back(
            {computeResiduals(doc_.field(), frame_->points_robot, p).overall.mean_m, p});
      std::stable_sort(ranked.begin(), ranked.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
      for (std::size_t i = 0; i < ranked.size(); ++i) (*located_)[i] = ranked[i].second;
    } catch (const std::exception& e) {
      located_status_->setText(e.what());
      return;
    }
    next_located_ = 0;
  }
  if (located_->empty()) {
    located_status_->setText("the localizer found no pose for this frame on this map");
    return;
  }
  const std::size_t i = next_located_++ % located_->size();
  located_status_->setText(QString("localizer pose %1 of %2").arg(i + 1).arg(located_->size()));
  setPose((*located_)[i]);
}

void CheckPanel::update(const EditorDocument& doc) {
  if (located_ && !sameField(doc.field(), doc_.field(), 0.0)) {
    located_.reset();  // the map changed: the poses must be computed again
    located_status_->clear();
  }
  doc_ = doc;
  report_ = {};
  table_->setRowCount(0);
  QGraphicsItemGroup* overlay = view_->overlay();
  for (QGraphicsItem* item : overlay->childItems()) delete item;
  if (!frame_) return;
  const Pose2 p = pose();
  report_ = computeResiduals(doc.field(), frame_->points_robot, p);
  // Points coloured by their distance to the map: cyan within 5 cm, magenta beyond.
  for (const Eigen::Vector2d& q : frame_->points_robot) {
    const Eigen::Vector2d f = p.transform(q);
    auto* dot = new QGraphicsEllipseItem(-0.03, -0.03, 0.06, 0.06);
    dot->setPos(toScene(f));
    const double d = nearestFeature(doc.field(), f).distance_m;
    dot->setBrush(d <= 0.05 ? QColor(0, 220, 255) : QColor(255, 0, 200));
    dot->setPen(Qt::NoPen);
    overlay->addToGroup(dot);
  }
  auto* robot = new QGraphicsEllipseItem(-0.1, -0.1, 0.2, 0.2);
  robot->setPos(toScene(p.translation()));
  robot->setPen(QPen(QColor(255, 0, 200), 0.03));
  overlay->addToGroup(robot);
  auto* heading = new QGraphicsLineItem(
      QLineF(toScene(p.translation()), toScene(p.transform(Eigen::Vector2d(0.3, 0.0)))));
  heading->setPen(QPen(QColor(255, 0, 200), 0.03));
  overlay->addToGroup(heading);

  auto row = [&](const QString& name, const ResidualStats& s) {
    const int r = table_->rowCount();
    table_->insertRow(r);
    table_->setItem(r, 0, new QTableWidgetItem(name));
    table_->setItem(r, 1, new QTableWidgetItem(QString::number(s.count)));
    table_->setItem(r, 2, new QTableWidgetItem(centimetres(s.mean_m)));
    table_->setItem(r, 3, new QTableWidgetItem(centimetres(s.p95_m)));
  };
  row(QString("overall (%1 unmatched)").arg(report_.unmatched), report_.overall);
  for (const FeatureResidual& f : report_.features) {
    const FeatureId id = doc.idAt(static_cast<EditorKind>(f.feature.kind), f.feature.index);
    row(QString::fromStdString(describeFeatureId(id) + " " + describeFeature(f.feature)), f.stats);
  }
}

}  // namespace houghloc::fieldmap
