#include "tools/fieldmap/viewer/robot_items.h"

#include <Eigen/Eigenvalues>
#include <QFont>
#include <QGraphicsEllipseItem>
#include <QGraphicsLineItem>
#include <QGraphicsSimpleTextItem>
#include <QPen>
#include <cmath>

#include "field_models/pose2.h"
#include "tools/fieldmap/editor/field_view.h"

namespace houghloc::fieldmap {
namespace {

constexpr double kRad2Deg = 180.0 / M_PI;

const char* stateName(int state) {
  static const char* names[] = {"INITIALIZING", "TRACKING", "AMBIGUOUS", "LOST"};
  return state >= 0 && state < 4 ? names[state] : "?";
}

/// A robot marker: circle of 0.08 m radius and a 0.35 m heading line.
void addRobot(const Pose2& p, const QPen& pen, ViewerItem role, QGraphicsItemGroup* group) {
  auto* body = new QGraphicsEllipseItem(-0.08, -0.08, 0.16, 0.16);
  body->setPos(toScene(p.translation()));
  body->setPen(pen);
  body->setData(kViewerRole, static_cast<int>(role));
  group->addToGroup(body);
  auto* heading = new QGraphicsLineItem(
      QLineF(toScene(p.translation()), toScene(p.transform(Eigen::Vector2d(0.35, 0.0)))));
  heading->setPen(pen);
  group->addToGroup(heading);
}

}  // namespace

Ellipse2 twoSigmaEllipse(const double c[9]) {
  Eigen::Matrix2d xy;
  xy << c[0], c[1], c[3], c[4];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(0.5 * (xy + xy.transpose()));
  if (eig.info() != Eigen::Success || eig.eigenvalues()(0) < 0.0) return {};
  const Eigen::Vector2d major = eig.eigenvectors().col(1);
  return {2.0 * std::sqrt(eig.eigenvalues()(1)), 2.0 * std::sqrt(eig.eigenvalues()(0)),
          std::atan2(major.y(), major.x())};
}

void addRobotItems(const RobotView& robot, const QColor& color, QGraphicsItemGroup* group) {
  if (robot.ground_truth && !robot.ground_truth->hypotheses.empty()) {
    const pose_hypothesis_t& g = robot.ground_truth->hypotheses.front();
    QPen pen(Qt::white, 0.04, Qt::DashLine);
    addRobot(Pose2(g.x, g.y, g.theta), pen, ViewerItem::kGroundTruth, group);
  }
  if (!robot.hypotheses) return;
  const std::vector<pose_hypothesis_t>& hs = robot.hypotheses->hypotheses;
  for (std::size_t i = 0; i < hs.size(); ++i) {
    const pose_hypothesis_t& h = hs[i];
    const Pose2 pose(h.x, h.y, h.theta);
    QColor c = color;
    c.setAlphaF(i == 0 ? 1.0 : 0.55);  // the best one solid
    const Ellipse2 e = twoSigmaEllipse(h.covariance);
    // At least 5 cm across, so a confident hypothesis stays visible.
    const double a = std::max(e.a_m, 0.05), b = std::max(e.b_m, 0.05);
    auto* ellipse = new QGraphicsEllipseItem(-a, -b, 2 * a, 2 * b);
    ellipse->setPos(toScene(pose.translation()));
    ellipse->setRotation(-e.angle_rad * kRad2Deg);  // scene y is flipped
    ellipse->setPen(QPen(c, 0.03));
    QColor fill = c;
    fill.setAlphaF(0.2);
    ellipse->setBrush(fill);
    ellipse->setData(kViewerRole, static_cast<int>(ViewerItem::kHypothesisEllipse));
    group->addToGroup(ellipse);
    addRobot(pose, QPen(c, 0.04), ViewerItem::kHypothesisPose, group);
    auto* label = new QGraphicsSimpleTextItem(QString::number(h.weight, 'f', 2));
    label->setBrush(c);
    label->setFont(QFont("Sans", 10));
    label->setFlag(QGraphicsItem::ItemIgnoresTransformations);
    label->setPos(toScene(pose.translation() + Eigen::Vector2d(0.2, 0.2)));
    group->addToGroup(label);
  }
  if (hs.empty() || !robot.points) return;
  const Pose2 best(hs[0].x, hs[0].y, hs[0].theta);
  for (int i = 0; i < robot.points->num_points; ++i) {
    const Eigen::Vector2d f =
        best.transform(Eigen::Vector2d(robot.points->x[i], robot.points->y[i]));
    auto* dot = new QGraphicsEllipseItem(-0.03, -0.03, 0.06, 0.06);
    dot->setPos(toScene(f));
    dot->setBrush(color.lighter(140));
    dot->setPen(Qt::NoPen);
    dot->setData(kViewerRole, static_cast<int>(ViewerItem::kLinePoint));
    group->addToGroup(dot);
  }
}

QString robotSummary(const std::string& prefix, const RobotView& robot) {
  QString s = QString::fromStdString(prefix.empty() ? std::string("(no prefix)") : prefix) + ": ";
  if (robot.status) {
    const localizer_status_t& st = *robot.status;
    s += QString("%1, cycle %2 ms, %3 of %4 points used, %5 frames")
             .arg(stateName(st.state))
             .arg(st.cycle_time_ms, 0, 'f', 1)
             .arg(st.points_used)
             .arg(st.points_in)
             .arg(st.frames_processed);
    if (!st.message.empty()) s += " - " + QString::fromStdString(st.message);
  } else {
    s += "no status yet";
  }
  if (robot.hypotheses) {
    s += QString("; %1 hypotheses (%2)")
             .arg(robot.hypotheses->num_hypotheses)
             .arg(stateName(robot.hypotheses->status));
  }
  return s;
}

}  // namespace houghloc::fieldmap
