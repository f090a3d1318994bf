#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose2.h"
#include "tools/render/ground_shader.h"
#include "tools/render/primitives.h"
#include "tools/render/scenario.h"

namespace houghloc {

/// Objects of one frame: shapes for the ray caster and their contact shadows.
struct SceneObjects {
  std::vector<Primitive> primitives;
  std::vector<ShadowDisc> shadows;
  void append(const SceneObjects& other);
};

/// Both goals: posts, crossbar, the white frame lying on the ground behind the goal line, the
/// upper frame and the nets.
SceneObjects makeGoals(const FieldModel& field, const SceneConfig& scene);

/// Spectators standing on the hall floor around the carpet (seeded).
SceneObjects makePeople(const FieldModel& field, const SceneConfig& scene, const RoomBox& room,
                        std::uint32_t seed);

/// A humanoid robot of `height_m` (NAO proportions: white shell, dark joints, team jersey)
/// standing at field_T_robot; gait_phase (rad) swings the legs while walking.
void addRobot(const Pose2& field_T_robot, double height_m, const Eigen::Vector3f& jersey,
              double gait_phase, bool walking, SceneObjects& out);

/// The rendering robot's own feet (seen by a camera looking steeply down).
void addOwnFeet(const Pose2& field_T_robot, double height_m, double gait_phase, bool walking,
                SceneObjects& out);

/// A black-and-white ball of `diameter_m` resting at `center` (field frame, on the ground),
/// turned by `spin` (its rolling).
void addBall(const Eigen::Vector2d& center, double diameter_m, const Eigen::Matrix3d& spin,
             SceneObjects& out);

/// Jersey colour of a team name (red, blue, black, yellow, green, white).
Eigen::Vector3f teamColour(const std::string& team);

}  // namespace houghloc
