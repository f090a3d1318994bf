#pragma once

#include <filesystem>
#include <string>

#include "field_models/standard_fields.h"
#include "tools/render/recording_renderer.h"
#include "vision/camera_presets.h"

namespace houghloc {

/// A render job for a standard field and camera preset into a fresh folder of the build tree.
/// camera "nao": the NAO's top and bottom camera taking turns (RenderJob::rig).
inline RenderJob testJob(const std::string& field, const std::string& camera,
                         const std::string& folder) {
  RenderJob job;
  job.field = makeStandardField(field);
  if (camera == kNaoCameraRig) {
    useNaoCameraRig(&job);
  } else {
    const CameraPreset preset = cameraPreset(camera);
    job.intrinsics = preset.intrinsics;
    job.mount = preset.robot_T_camera;
  }
  job.out_dir = std::string(HOUGHLOC_BINARY_DIR) + "/test_renders/" + folder;
  std::filesystem::remove_all(job.out_dir);
  return job;
}

}  // namespace houghloc
