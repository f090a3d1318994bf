#include "tools/fieldmap/editor/field_view.h"

#include <QGraphicsEllipseItem>
#include <QGraphicsPathItem>
#include <QGraphicsRectItem>
#include <QMouseEvent>
#include <QScrollBar>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace houghloc::fieldmap {
namespace {

constexpr int kFeatureKey = 0;  // QGraphicsItem::data keys
constexpr int kHandleKey = 1;
constexpr double kHandlePx = 9.0;

QVariant encode(const FeatureId& f) { return QPoint(static_cast<int>(f.kind), f.id); }
FeatureId decode(const QVariant& v) {
  const QPoint p = v.toPoint();
  return {static_cast<EditorKind>(p.x()), p.y()};
}

QPainterPath arcPath(const Arc2& arc) {
  QPainterPath path;
  const int steps = std::max(8, static_cast<int>(arc.sweep_rad / 0.05));
  for (int i = 0; i <= steps; ++i) {
    const QPointF p = toScene(arc.pointAt(arc.start_rad + arc.sweep_rad * i / steps));
    i == 0 ? path.moveTo(p) : path.lineTo(p);
  }
  return path;
}

QPainterPath markPath(const Mark& m) {
  QPainterPath path;
  const QPointF c = toScene(m.center);
  const double h = 0.5 * m.size;
  if (m.shape == MarkShape::kDot) {
    path.addEllipse(c, h, h);
  } else {
    path.moveTo(c + QPointF(-h, 0));
    path.lineTo(c + QPointF(h, 0));
    path.moveTo(c + QPointF(0, -h));
    path.lineTo(c + QPointF(0, h));
  }
  return path;
}

/// Posts and the net behind the goal line, on the side away from the centre.
QPainterPath goalPath(const Goal& g) {
  QPainterPath path;
  const double side = g.center.x() >= 0.0 ? 1.0 : -1.0;
  const double hw = 0.5 * g.inner_width + 0.5 * g.post_diameter;
  const double r = 0.5 * g.post_diameter;
  for (double s : {-1.0, 1.0})
    path.addEllipse(toScene(g.center + Eigen::Vector2d(0, s * hw)), r, r);
  path.moveTo(toScene(g.center + Eigen::Vector2d(0, -hw)));
  path.lineTo(toScene(g.center + Eigen::Vector2d(side * g.depth, -hw)));
  path.lineTo(toScene(g.center + Eigen::Vector2d(side * g.depth, hw)));
  path.lineTo(toScene(g.center + Eigen::Vector2d(0, hw)));
  return path;
}

}  // namespace

QPointF toScene(const Eigen::Vector2d& p) { return {p.x(), -p.y()}; }
Eigen::Vector2d toField(const QPointF& s) { return {s.x(), -s.y()}; }

FieldView::FieldView(QWidget* parent) : QGraphicsView(parent) {
  setScene(new QGraphicsScene(this));
  setRenderHint(QPainter::Antialiasing);
  setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
  setViewportUpdateMode(QGraphicsView::FullViewportUpdate);
  setMinimumSize(400, 300);
}

void FieldView::showDocument(const EditorDocument& doc, const std::vector<FeatureId>& selection) {
  field_ = doc.field();
  selection_ = selection;
  drag_.reset();
  scene()->clear();
  const double mx = field_.outerHalfLength() + 1.0, my = field_.outerHalfWidth() + 1.0;
  scene()->setSceneRect(-mx, -my, 2 * mx, 2 * my);
  for (const FeatureId& f : doc.allFeatures()) {
    const bool selected = std::find(selection.begin(), selection.end(), f) != selection.end();
    addFeatureItems(doc, f, selected);
  }
  for (const FeatureId& f : selection)
    if (doc.contains(f)) addHandles(doc, f);
  overlay_ = scene()->createItemGroup({});
  overlay_->setZValue(5);
  resetCachedContent();
  viewport()->update();
}

void FieldView::addFeatureItems(const EditorDocument& doc, const FeatureId& f, bool selected) {
  QPainterPath path;
  switch (f.kind) {
    case EditorKind::kSegment:
      path.moveTo(toScene(doc.segment(f).a));
      path.lineTo(toScene(doc.segment(f).b));
      break;
    case EditorKind::kArc:
      path = arcPath(doc.arc(f));
      break;
    case EditorKind::kMark:
      path = markPath(doc.mark(f));
      break;
    case EditorKind::kGoal:
      path = goalPath(doc.goal(f));
      break;
  }
  const bool goal = f.kind == EditorKind::kGoal;
  const QColor color = selected ? QColor(255, 140, 0) : goal ? QColor(250, 230, 60) : Qt::white;
  QPen pen(color, goal ? 0.03 : std::max(field_.line_width, 0.01));
  pen.setCapStyle(Qt::FlatCap);
  auto* item = scene()->addPath(path, pen,
                                f.kind == EditorKind::kMark && doc.mark(f).shape == MarkShape::kDot
                                    ? QBrush(color)
                                    : QBrush());
  item->setData(kFeatureKey, encode(f));
  item->setZValue(goal ? 1 : 2);
}

void FieldView::addHandles(const EditorDocument& doc, const FeatureId& f) {
  std::vector<std::pair<Handle, Eigen::Vector2d>> handles;
  switch (f.kind) {
    case EditorKind::kSegment:
      handles = {{Handle::kStart, doc.segment(f).a}, {Handle::kEnd, doc.segment(f).b}};
      break;
    case EditorKind::kArc: {
      const Arc2& a = doc.arc(f);
      handles = {{Handle::kCenter, a.center},
                 {Handle::kRadius, a.pointAt(a.start_rad + 0.5 * a.sweep_rad)}};
      if (!a.isFullCircle()) {
        handles.push_back({Handle::kArcStart, a.pointAt(a.start_rad)});
        handles.push_back({Handle::kArcEnd, a.pointAt(a.start_rad + a.sweep_rad)});
      }
      break;
    }
    case EditorKind::kMark:
      handles = {{Handle::kCenter, doc.mark(f).center}};
      break;
    case EditorKind::kGoal:
      handles = {{Handle::kCenter, doc.goal(f).center}};
      break;
  }
  for (const auto& [handle, p] : handles) {
    auto* item = scene()->addRect(-kHandlePx / 2, -kHandlePx / 2, kHandlePx, kHandlePx,
                                  QPen(Qt::black, 0), QBrush(QColor(255, 140, 0)));
    item->setFlag(QGraphicsItem::ItemIgnoresTransformations);  // constant size in pixels
    item->setPos(toScene(p));
    item->setZValue(10);
    item->setData(kFeatureKey, encode(f));
    item->setData(kHandleKey, static_cast<int>(handle));
  }
}

void FieldView::fitField() {
  const double hx = field_.outerHalfLength() + 0.2, hy = field_.outerHalfWidth() + 0.2;
  fitInView(QRectF(-hx, -hy, 2 * hx, 2 * hy), Qt::KeepAspectRatio);
}

void FieldView::drawBackground(QPainter* painter, const QRectF& rect) {
  painter->fillRect(rect, QColor(60, 60, 60));
  const double hx = field_.outerHalfLength(), hy = field_.outerHalfWidth();
  painter->fillRect(QRectF(-hx, -hy, 2 * hx, 2 * hy), QColor(40, 130, 50));
  // Metric grid: 0.5 m lines, every metre darker.
  for (int k = static_cast<int>(std::floor(rect.left() * 2)); k <= rect.right() * 2; ++k) {
    painter->setPen(QPen(QColor(0, 0, 0, k % 2 == 0 ? 70 : 30), 0));
    painter->drawLine(QPointF(0.5 * k, rect.top()), QPointF(0.5 * k, rect.bottom()));
  }
  for (int k = static_cast<int>(std::floor(rect.top() * 2)); k <= rect.bottom() * 2; ++k) {
    painter->setPen(QPen(QColor(0, 0, 0, k % 2 == 0 ? 70 : 30), 0));
    painter->drawLine(QPointF(rect.left(), 0.5 * k), QPointF(rect.right(), 0.5 * k));
  }
  // Axes of the field frame: x red, y blue, 1 m long arrows from the centre mark.
  painter->setPen(QPen(QColor(220, 40, 40), 0.03));
  painter->drawLine(QPointF(0, 0), toScene({1.0, 0.0}));
  painter->drawLine(toScene({1.0, 0.0}), toScene({0.9, 0.05}));
  painter->drawLine(toScene({1.0, 0.0}), toScene({0.9, -0.05}));
  painter->setPen(QPen(QColor(40, 80, 230), 0.03));
  painter->drawLine(QPointF(0, 0), toScene({0.0, 1.0}));
  painter->drawLine(toScene({0.0, 1.0}), toScene({0.05, 0.9}));
  painter->drawLine(toScene({0.0, 1.0}), toScene({-0.05, 0.9}));
}

void FieldView::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::MiddleButton || event->button() == Qt::RightButton) {
    pan_from_ = event->pos();
    return;
  }
  if (event->button() != Qt::LeftButton) return;
  const QPointF scene_pos = mapToScene(event->pos());
  if ((event->modifiers() & Qt::ShiftModifier) && on_pose_dragged) {
    drag_ = Drag{std::nullopt, Handle::kCenter, scene_pos, nullptr, false, true};
    return;
  }
  QGraphicsItem* hit = nullptr;
  for (QGraphicsItem* item : items(QRect(event->pos() - QPoint(4, 4), QSize(9, 9)))) {
    if (!item->data(kFeatureKey).isValid()) continue;
    if (item->data(kHandleKey).isValid()) {  // handles win over lines under them
      hit = item;
      break;
    }
    if (!hit) hit = item;
  }
  if (hit && hit->data(kHandleKey).isValid()) {
    drag_ = Drag{decode(hit->data(kFeatureKey)), static_cast<Handle>(hit->data(kHandleKey).toInt()),
                 scene_pos, hit, false};
    return;
  }
  std::vector<FeatureId> selection =
      event->modifiers() & Qt::ControlModifier ? selection_ : std::vector<FeatureId>{};
  if (hit) {
    const FeatureId f = decode(hit->data(kFeatureKey));
    const auto it = std::find(selection_.begin(), selection_.end(), f);
    if (it != selection_.end() && !(event->modifiers() & Qt::ControlModifier)) {
      drag_ = Drag{std::nullopt, Handle::kCenter, scene_pos, nullptr, false};  // move selection
      return;
    }
    const auto in = std::find(selection.begin(), selection.end(), f);
    in == selection.end() ? selection.push_back(f) : (void)selection.erase(in);
  }
  if (on_selection) on_selection(selection);
}

void FieldView::mouseMoveEvent(QMouseEvent* event) {
  if (pan_from_) {
    const QPoint d = event->pos() - *pan_from_;
    pan_from_ = event->pos();
    horizontalScrollBar()->setValue(horizontalScrollBar()->value() - d.x());
    verticalScrollBar()->setValue(verticalScrollBar()->value() - d.y());
    return;
  }
  if (!drag_) return;
  drag_->moved = true;
  if (drag_->pose) {  // live: the points follow the cursor
    const QPointF scene_pos = mapToScene(event->pos());
    on_pose_dragged(toField(scene_pos) - toField(drag_->start_scene));
    drag_->start_scene = scene_pos;
    return;
  }
  if (drag_->feature && drag_->item) {
    Eigen::Vector2d p = toField(mapToScene(event->pos()));
    if (snap) p = snap(*drag_->feature, drag_->handle, p);
    drag_->item->setPos(toScene(p));
  }
}

void FieldView::mouseReleaseEvent(QMouseEvent* event) {
  if (pan_from_) {
    pan_from_.reset();
    return;
  }
  if (!drag_) return;
  const Drag drag = *drag_;
  drag_.reset();
  // A release away from the press counts as a drag even without move events in between.
  const QPoint press = mapFromScene(drag.start_scene);
  if (!drag.moved && (event->pos() - press).manhattanLength() < 3) return;
  const QPointF scene_pos = mapToScene(event->pos());
  if (drag.pose) {
    on_pose_dragged(toField(scene_pos) - toField(drag.start_scene));
  } else if (drag.feature) {
    Eigen::Vector2d p = toField(scene_pos);
    if (snap) p = snap(*drag.feature, drag.handle, p);
    if (on_handle_dragged) on_handle_dragged(*drag.feature, drag.handle, p);
  } else if (on_selection_moved) {
    on_selection_moved(toField(scene_pos) - toField(drag.start_scene));
  }
}

void FieldView::wheelEvent(QWheelEvent* event) {
  if ((event->modifiers() & Qt::ShiftModifier) && on_pose_turned) {
    on_pose_turned(event->angleDelta().y() / 120.0 * M_PI / 180.0);  // 1 deg per wheel step
    return;
  }
  const double factor = std::pow(1.0015, event->angleDelta().y());
  scale(factor, factor);  // AnchorUnderMouse keeps the point under the cursor in place
}

}  // namespace houghloc::fieldmap
