#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_models/ground_points.h"

namespace houghloc {

/// A disc on the ground hiding what is behind it (robot frame).
struct Occluder {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double radius_m = 0.2;
};

/// Range at which the view along angle phi (robot frame) ends: an occluder's near side (0 when
/// the robot stands in one) or max_range.
double visibleRange(double phi, double max_range, const std::vector<Occluder>& occluders);

/// Whether the ground point p_robot is visible: inside the wedge and not behind an occluder.
bool wedgeVisible(const Eigen::Vector2d& p_robot, double half_angle_rad, double min_range_m,
                  double max_range_m, const std::vector<Occluder>& occluders);

/// The wedge minus the occluders' shadows as one polygon (robot frame), clipped by the convex
/// polygon `clip` (Sutherland-Hodgman).
GroundPolygon visibleRegion(double half_angle_rad, double min_range_m, double max_range_m,
                            const std::vector<Occluder>& occluders, const GroundPolygon& clip);

}  // namespace houghloc
