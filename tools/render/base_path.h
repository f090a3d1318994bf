#pragma once

#include <memory>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose2.h"
#include "tools/render/scenario.h"

namespace houghloc {

/// A robot's undisturbed motion over "path time" tau (s): where it is and how fast it walks.
/// Kidnaps and falls are applied on top (Trajectory).
class BasePath {
 public:
  virtual ~BasePath() = default;
  virtual Pose2 pose(double tau_s) const = 0;
  /// Walking speed (m/s) at tau, for the gait's camera wobble.
  virtual double speed(double tau_s) const = 0;
  /// Length in time of one lap (looping paths) or of the whole path (s).
  virtual double duration() const = 0;
  /// True for a path that stays at one spot (spin): kidnaps then move the spot.
  virtual bool stationary() const { return false; }
};

/// Figure of eight through the centre circle and both halves at constant speed, heading along
/// the path (built-in `walk`).
std::unique_ptr<BasePath> makeFigureEight(const FieldModel& field, double speed_mps);
/// Turning on the spot (built-in `spin`).
std::unique_ptr<BasePath> makeSpin(const Pose2& where, double rate_rad_s);
/// Straight lines between waypoints (scenario `trajectory.waypoints`).
std::unique_ptr<BasePath> makeWaypointPath(const std::vector<Waypoint>& waypoints, bool loop,
                                           double turn_speed_rad_s);

}  // namespace houghloc
