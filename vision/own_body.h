#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_models/pose3.h"
#include "vision/ground_projection.h"

namespace houghloc {

/// The robot's own feet on the ground, a box in the robot frame (DESIGN §3: origin on the
/// ground between the feet, x forward). A downward camera (a NAO's bottom one) sees the feet;
/// their corners and toes, cut by the image border or each other, give runs as narrow as a
/// line. A field line under the feet is hidden by them anyway. Sized for a NAO: its feet reach
/// 0.13 m ahead of the origin in a walking step and 0.095 m to each side, and their tops, 3 cm
/// above the ground, project up to 1 cm beyond. All zero: nothing is dropped.
struct OwnBodyConfig {
  double front_m = 0.14;  ///< box from x = -back_m to x = front_m
  double back_m = 0.1;
  double half_width_m = 0.11;  ///< |y| below this
};

/// Whether a robot-frame ground point lies on the robot's own feet.
bool onOwnBody(const Eigen::Vector2d& p_robot, const OwnBodyConfig& config);

/// The rays whose ground point (with robot_T_camera) is not on the robot's own feet; rays that
/// miss the ground are kept (later steps drop them by range).
std::vector<SpotRay> dropSpotsOnOwnBody(const std::vector<SpotRay>& rays,
                                        const Pose3& robot_T_camera, const OwnBodyConfig& config,
                                        int* dropped = nullptr);

}  // namespace houghloc
