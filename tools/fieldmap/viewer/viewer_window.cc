#include "tools/fieldmap/viewer/viewer_window.h"

#include <QGraphicsItemGroup>
#include <QLabel>
#include <QSlider>
#include <QVBoxLayout>
#include <algorithm>

#include "tools/fieldmap/editor/field_view.h"
#include "tools/fieldmap/viewer/robot_items.h"

namespace houghloc::fieldmap {
namespace {

/// One colour per robot, in prefix order.
QColor robotColor(std::size_t i) {
  static const QColor colors[] = {QColor(255, 60, 40), QColor(40, 120, 255), QColor(255, 200, 0),
                                  QColor(200, 60, 255)};
  return colors[i % 4];
}

}  // namespace

ViewerWindow::ViewerWindow(const FieldModel& field, std::vector<std::string> prefixes,
                           QString source)
    : prefixes_(prefixes.empty() ? std::vector<std::string>{""} : std::move(prefixes)),
      source_(std::move(source)),
      state_(prefixes_),
      view_(new FieldView),
      status_(new QLabel),
      time_(new QLabel),
      slider_(new QSlider(Qt::Horizontal)) {
  setWindowTitle("houghloc viewer - " + QString::fromStdString(field.name));
  auto* central = new QWidget;
  auto* layout = new QVBoxLayout(central);
  layout->addWidget(view_, 1);
  layout->addWidget(status_);
  auto* row = new QHBoxLayout;
  row->addWidget(slider_, 1);
  row->addWidget(time_);
  layout->addLayout(row);
  slider_->hide();
  time_->hide();
  setCentralWidget(central);
  resize(1100, 800);
  view_->showDocument(EditorDocument(field), {});
  connect(slider_, &QSlider::valueChanged, this, [this](int ms) {
    if (log_) seek(log_->startUs() + std::int64_t{ms} * 1000);
  });
  showState(state_);
}

void ViewerWindow::showState(const ViewerState& state) {
  state_ = state;
  QGraphicsItemGroup* overlay = view_->overlay();
  for (QGraphicsItem* item : overlay->childItems()) delete item;
  QStringList lines;
  for (std::size_t i = 0; i < state_.prefixes().size(); ++i) {
    const std::string& prefix = state_.prefixes()[i];
    addRobotItems(state_.robot(prefix), robotColor(i), overlay);
    if (!state_.empty()) lines << robotSummary(prefix, state_.robot(prefix));
  }
  if (state_.empty()) {
    QStringList channels;
    for (const std::string& p : state_.prefixes())
      channels << QString::fromStdString(p) + "HYPOTHESES";
    lines << "waiting for messages (" + channels.join(", ") + ", ...) from " + source_;
  }
  if (state_.malformed() > 0)
    lines << QString("%1 malformed messages ignored").arg(state_.malformed());
  status_->setText(lines.join("\n"));
}

void ViewerWindow::setLog(std::shared_ptr<const LogIndex> log) {
  log_ = std::move(log);
  // Rounded up, so the slider's end reaches the last event.
  const int span_ms = static_cast<int>((log_->endUs() - log_->startUs() + 999) / 1000);
  slider_->setRange(0, span_ms);
  slider_->setSingleStep(33);
  slider_->setPageStep(1000);
  slider_->show();
  time_->show();
  seek(log_->startUs());
}

void ViewerWindow::seek(std::int64_t t_us) {
  if (!log_) return;
  t_us = std::clamp(t_us, log_->startUs(), log_->endUs());
  // Rounded up like the range, so the last event keeps the slider at its end.
  slider_->blockSignals(true);
  slider_->setValue(static_cast<int>((t_us - log_->startUs() + 999) / 1000));
  slider_->blockSignals(false);
  time_->setText(QString("%1 s of %2 s")
                     .arg((t_us - log_->startUs()) * 1e-6, 0, 'f', 2)
                     .arg((log_->endUs() - log_->startUs()) * 1e-6, 0, 'f', 2));
  showState(log_->stateAt(t_us, prefixes_));
}

int ViewerWindow::countItems(int role) const {
  int n = 0;
  for (const QGraphicsItem* item : view_->overlay()->childItems())
    if (item->data(kViewerRole).toInt() == role) ++n;
  return n;
}

}  // namespace houghloc::fieldmap
