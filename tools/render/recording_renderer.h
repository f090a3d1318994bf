#pragma once

#include <functional>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose3.h"
#include "tools/render/scenario.h"
#include "vision/camera_model.h"

namespace houghloc {

/// One camera of a multi-camera robot, e.g. a NAO's top or bottom camera.
struct RigCamera {
  std::string id;  ///< frames.csv camera column and cameras/<id>.yaml
  CameraIntrinsics intrinsics;
  Pose3 mount;  ///< robot_T_camera of the standing robot with the head centred
};

/// Everything one render run needs; the command line fills it from the scenario and options.
struct RenderJob {
  Scenario scenario;
  FieldModel field;
  CameraIntrinsics intrinsics;
  Pose3 mount;  ///< robot_T_camera of the standing robot with the head centred
  /// Several cameras taking turns, as a NAO reads its top and bottom camera alternately: frame
  /// i is taken by rig[i % rig.size()]. Empty: the single camera above (camera.yaml, no camera
  /// column). The first rig camera should equal intrinsics/mount (the robot's height uses it).
  std::vector<RigCamera> rig;
  std::string out_dir;
};

/// The camera name that selects the NAO pair below (`houghloc-render --camera nao`).
constexpr const char* kNaoCameraRig = "nao";

/// Makes the job a NAO's: its top and bottom camera (presets nao-top, nao-bottom) taking turns,
/// intrinsics and mount those of the top camera.
void useNaoCameraRig(RenderJob* job);

/// Called after each frame with (frames done, total).
using RenderProgress = std::function<void(int, int)>;

/// Renders a complete recorded folder (DESIGN §5.1): images/, frames.csv, camera.yaml,
/// groundtruth.csv, hints.csv, field.yaml, truth/visible.csv and truth/events.csv.
/// Single-threaded and seeded: the same job gives the same bytes.
void renderRecording(const RenderJob& job, const RenderProgress& progress = {});

}  // namespace houghloc
