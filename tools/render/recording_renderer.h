#pragma once

#include <functional>
#include <string>

#include "field_models/field_model.h"
#include "field_models/pose3.h"
#include "tools/render/scenario.h"
#include "vision/camera_model.h"

namespace houghloc {

/// Everything one render run needs; the command line fills it from the scenario and options.
struct RenderJob {
  Scenario scenario;
  FieldModel field;
  CameraIntrinsics intrinsics;
  Pose3 mount;  ///< robot_T_camera of the standing robot with the head centred
  std::string out_dir;
};

/// Called after each frame with (frames done, total).
using RenderProgress = std::function<void(int, int)>;

/// Renders a complete recorded folder (DESIGN §5.1): images/, frames.csv, camera.yaml,
/// groundtruth.csv, hints.csv, field.yaml, truth/visible.csv and truth/events.csv.
/// Single-threaded and seeded: the same job gives the same bytes.
void renderRecording(const RenderJob& job, const RenderProgress& progress = {});

}  // namespace houghloc
