#pragma once

#include <memory>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose2.h"
#include "tools/render/base_path.h"
#include "tools/render/scenario.h"

namespace houghloc {

/// The true state of the rendered robot at one instant.
struct RobotState {
  Pose2 field_T_robot;
  double pan_rad = 0.0;         ///< head yaw joint
  double tilt_rad = 0.0;        ///< head pitch joint, positive looks down
  double fall_phase = -1.0;     ///< < 0 upright; 0..1 from FALL_START to FALL_END
  double walk_speed_mps = 0.0;  ///< drives the gait's camera wobble
};

/// KIDNAP, FALL_START or FALL_END at t_s (truth/events.csv).
struct TrajectoryEvent {
  double t_s = 0.0;
  std::string event;
};

/// Ground-truth motion of the robot (DESIGN §5.4): a base path (built-in or waypoints) plus
/// kidnaps (the robot jumps; odometry does not see it) and falls (the robot stops, lies on its
/// back looking at the ceiling, and gets up a little displaced). Times in seconds from the first
/// frame; a function of time only, so motion blur can ask for any instant.
class Trajectory {
 public:
  Trajectory(const Scenario& scenario, const FieldModel& field);
  RobotState at(double t_s) const;
  /// Robot-frame motion from t0 to t1 as the legs made it: kidnaps and falls are not in it
  /// (odometry does not see them); random-poses frames do not move at all.
  Pose2 walkedMotion(double t0_s, double t1_s) const;
  const std::vector<TrajectoryEvent>& events() const { return events_; }
  /// random-poses: every frame is an independent pose.
  bool independentFrames() const { return random_poses_; }

 private:
  /// From t0 on: pose = K * path(tau0 + (t - t0)), or path(tau0) frozen during a fall.
  struct Piece {
    double t0 = 0.0;
    double tau0 = 0.0;
    Pose2 K;
    bool fallen = false;
    double fall_duration = 0.0;
    Pose2 fall_offset;  ///< robot-frame displacement the fall causes
  };
  void addKidnap(const KidnapConfig& kidnap, std::uint32_t salt);
  void addFall(const FallConfig& fall, std::uint32_t salt);
  Pose2 basePose(const Piece& piece, double t) const;
  const Piece& pieceAt(double t) const;
  double pan(double t) const;

  Scenario scenario_;
  FieldModel field_;
  std::unique_ptr<BasePath> path_;
  std::vector<Piece> pieces_;
  std::vector<TrajectoryEvent> events_;
  bool random_poses_ = false;
  bool head_sweeps_ = false;
};

}  // namespace houghloc
