#pragma once

#include <Eigen/Core>
#include <random>
#include <string>
#include <vector>

#include "field_models/pose2.h"
#include "tools/render/scenario.h"
#include "tools/render/scene_objects.h"
#include "tools/render/sensor_effects.h"

namespace houghloc {

class YamlMap;

/// The fault kinds a scenario's `faults` list may name (docs/render.md "Faults").
const std::vector<std::string>& faultKinds();

/// Reads one `faults[i]` mapping: kind, start_s, end_s and the parameters of that kind only (a
/// parameter of another kind is an unknown key).
void readFault(YamlMap& m, FaultConfig& fault);

/// Checks one fault (known kind, end after start, parameter ranges); throws
/// std::invalid_argument naming `faults[index]`.
void validateFault(const FaultConfig& fault, size_t index);

/// The first fault of `kind` active at t_s (start_s <= t_s < end_s), or null.
const FaultConfig* activeFault(const std::vector<FaultConfig>& faults, const std::string& kind,
                               double t_s);

/// The odometry step recorded for `walked` (the true robot-frame motion of a frame) ending at
/// t_s: scaled by an active odometry_scale fault's `scale`, translation and rotation alike.
Pose2 recordedOdometryStep(const std::vector<FaultConfig>& faults, const Pose2& walked, double t_s);

/// The error (rad) a camera_pitch_error fault adds to the recorded camera pitch at t_s.
double recordedPitchError(const std::vector<FaultConfig>& faults, double t_s);

/// Whether the frame at t_s is left out of the recording by a frame_drop fault (one draw from
/// rng per frame inside the fault's window, none outside it).
bool frameDropped(const std::vector<FaultConfig>& faults, double t_s, std::mt19937& rng);

/// The exposure time (ms) at t_s: a motion_blur fault's instead of the sensor's.
double exposureTimeAt(const SensorConfig& sensor, const std::vector<FaultConfig>& faults,
                      double t_s);

/// Exposure and light colour after the light_change faults: each scales the gain by `exposure`
/// and shifts the light colour to its `color_temperature_k`, ramping in over ramp_s from start_s
/// and back out over the ramp_s before end_s (the light is as before at end_s).
ExposureState applyLightFaults(ExposureState state, const std::vector<FaultConfig>& faults,
                               double t_s);

/// Robots of the robots_in_view faults active at t_s: `robots` of them `distance_m` in front of
/// the camera (field_T_robot turned by the head's pan), spread evenly over `spread_deg` across
/// the view, facing the camera, walking along with the robot.
SceneObjects faultRobots(const std::vector<FaultConfig>& faults, double t_s,
                         const Pose2& field_T_robot, double pan_rad, double robot_height_m);

}  // namespace houghloc
