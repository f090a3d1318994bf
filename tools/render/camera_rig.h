#pragma once

#include <Eigen/Core>
#include <random>

#include "field_models/pose3.h"
#include "tools/render/scenario.h"
#include "tools/render/trajectory.h"

namespace houghloc {

/// Pose3 from a rotation matrix R = Rz(yaw) Ry(pitch) Rx(roll) and a translation.
Pose3 poseFromRotation(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation);

/// The true robot_T_camera at time t: the camera's mount (preset) turned by the head's pan and
/// tilt about the neck, wobbling with the gait while walking, and tipped over backwards during a
/// fall so the camera looks at the ceiling.
Pose3 renderedCameraPose(const Pose3& mount, const RobotState& state, double t_s,
                         const Scenario& scenario);

/// What the robot believes (frames.csv cam_*): the rendered pose plus the scenario's bias and
/// per-frame noise (DESIGN §5.4 camera-pose error).
Pose3 recordedCameraPose(const Pose3& rendered, const CameraPoseError& error, std::mt19937& rng);

}  // namespace houghloc
