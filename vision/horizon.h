#pragma once

#include <vector>

#include "vision/camera_model.h"

namespace houghloc {

struct HorizonConfig {
  double margin_px = 4.0;  ///< scanning starts this far below the horizon (rays that flat see
                           ///< the ground too far away to be useful anyway)
};

/// First image row to scan in each column: just below the horizon computed from the camera pose
/// (per column, since with roll or distortion the horizon is not a row), clamped to
/// [0, height]. A column whose start row equals the height sees no ground.
std::vector<int> scanStartRows(const CameraModel& camera, const HorizonConfig& config = {});

}  // namespace houghloc
