#pragma once

#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose2.h"
#include "tools/render/scenario.h"
#include "tools/render/scene_objects.h"

namespace houghloc {

/// Robot height and ball diameter of a league, from the field's name and size (m).
double defaultRobotHeight(const FieldModel& field);
double defaultBallDiameter(const FieldModel& field);

/// Other robots and the ball, moving at constant velocity and bouncing off the carpet edge;
/// positions are a closed-form function of time (deterministic, any instant).
class MovingObjects {
 public:
  MovingObjects(const Scenario& scenario, const FieldModel& field);

  /// Their shapes at t_s. Robots closer than 0.3 m to `self` (the rendering robot) are left out
  /// rather than drawn through the camera.
  SceneObjects at(double t_s, const Pose2& self) const;

 private:
  struct Mover {
    Eigen::Vector2d start, velocity;  ///< m, m/s
    double theta = 0.0;
    Eigen::Vector3f jersey;
  };
  Eigen::Vector2d position(const Mover& m, double t, Eigen::Vector2d* velocity) const;

  std::vector<Mover> robots_;
  bool ball_ = false;
  Mover ball_mover_;
  double ball_diameter_ = 0.1;
  double robot_height_ = 0.58;
  Eigen::Vector2d bounds_;  ///< half extents the movers bounce within
};

}  // namespace houghloc
