#pragma once

#include <QColor>
#include <QGraphicsItemGroup>
#include <QString>

#include "tools/fieldmap/viewer_model/viewer_state.h"

namespace houghloc::fieldmap {

/// QGraphicsItem::data(kViewerRole) of the viewer's items, so tests can count them.
constexpr int kViewerRole = 7;
enum class ViewerItem { kHypothesisEllipse = 1, kHypothesisPose, kLinePoint, kGroundTruth };

/// Half axes (m) and angle (rad, field frame) of the 2-sigma ellipse of a row-major 3x3 (x, y,
/// theta) covariance's position block; zero axes for a non-positive one.
struct Ellipse2 {
  double a_m = 0.0, b_m = 0.0, angle_rad = 0.0;
};
Ellipse2 twoSigmaEllipse(const double covariance[9]);

/// Adds one robot's items to `group` in `color`: every hypothesis (2-sigma ellipse, heading,
/// weight), the line points at the best hypothesis, and the ground truth.
void addRobotItems(const RobotView& robot, const QColor& color, QGraphicsItemGroup* group);

/// One line of text for the robot: state, cycle time, points, hypotheses, message.
QString robotSummary(const std::string& prefix, const RobotView& robot);

}  // namespace houghloc::fieldmap
