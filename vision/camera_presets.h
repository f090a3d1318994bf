#pragma once

#include <string>
#include <vector>

#include "field_models/pose3.h"
#include "vision/camera_model.h"

namespace houghloc {

/// A camera as it sits on a typical robot: intrinsics plus the default robot_T_camera.
struct CameraPreset {
  std::string name;
  CameraIntrinsics intrinsics;
  Pose3 robot_T_camera;
};

/// nao-top, nao-bottom, kid-wide, adult (issue 4), wide-pinhole.
std::vector<std::string> cameraPresetNames();
/// Throws std::invalid_argument naming the unknown preset and listing the known ones.
CameraPreset cameraPreset(const std::string& name);

}  // namespace houghloc
