#pragma once

#include <Eigen/Core>
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
