#pragma once

#include <cstdint>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/ground_points.h"
#include "field_models/pose2.h"

namespace houghloc::testing {

/// A minimal synthetic walk for tracker tests and the tracking benchmark, until the shared
/// generator (tools/synthetic, houghloc_synthetic) lands: ground truth along a figure eight,
/// cumulative odometry with noise and slip, and ground points sampled on the map lines inside a
/// camera wedge that pans with the head, with range-dependent noise and outliers.
struct ScenarioConfig {
  int frames = 900;
  double fps = 30.0;
  double half_extent_x_m = 3.0;  ///< figure eight: x = ax sin(w t), y = ay sin(2 w t)
  double half_extent_y_m = 1.8;
  double period_s = 60.0;        ///< of one figure eight
  double odometry_noise = 0.10;  ///< per-step relative std of translation and rotation
  double odometry_slip = 0.05;   ///< systematic under-reading of translation (slip)
  double head_pan_rad = 0.9;     ///< amplitude of the head pan
  double head_period_s = 4.0;
  double fov_rad = 1.0;  ///< horizontal field of view of the wedge
  double min_range_m = 0.3;
  double max_range_m = 4.0;
  int max_points = 300;              ///< line points per frame (outliers come on top)
  double point_noise_m = 0.01;       ///< std at zero range, m
  double point_noise_per_m = 0.008;  ///< added std per metre of range
  double outlier_fraction = 0.10;
  double sample_spacing_m = 0.01;  ///< along the map lines
  /// Kidnap at this frame (negative: none): the robot is carried to kidnap_to and walks on from
  /// there; odometry does not see it.
  int kidnap_frame = -1;
  Pose2 kidnap_to;
  std::uint32_t seed = 1;
};

struct ScenarioFrame {
  std::int64_t t_us = 0;
  Pose2 field_T_robot;  ///< ground truth
  Pose2 odometry;       ///< cumulative, noisy
  GroundPoints points;
};

std::vector<ScenarioFrame> makeScenario(const FieldModel& field, const ScenarioConfig& config);

/// Points only: what a robot at field_T_robot sees with the wedge pointing at `pan_rad`.
GroundPoints samplePoints(const FieldModel& field, const Pose2& field_T_robot, double pan_rad,
                          const ScenarioConfig& config, std::uint32_t seed);

}  // namespace houghloc::testing
