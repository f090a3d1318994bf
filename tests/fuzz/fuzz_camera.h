#pragma once

// The camera of the image-fuzzing targets (vision, node): a preset's intrinsics scaled to a
// small image, so that every input costs little.
#include <string>

#include "vision/camera_presets.h"

namespace houghloc::fuzz {

/// `preset`'s focal lengths scaled to `width` (its aspect kept), the principal point centred.
inline CameraIntrinsics scaledCamera(const std::string& preset, int width, int height) {
  CameraIntrinsics intrinsics = cameraPreset(preset).intrinsics;
  const double scale = static_cast<double>(width) / intrinsics.image_width;
  intrinsics.camera_matrix(0, 0) *= scale;
  intrinsics.camera_matrix(1, 1) *= scale;
  intrinsics.camera_matrix(0, 2) = 0.5 * width;
  intrinsics.camera_matrix(1, 2) = 0.5 * height;
  intrinsics.image_width = width;
  intrinsics.image_height = height;
  return intrinsics;
}

}  // namespace houghloc::fuzz
