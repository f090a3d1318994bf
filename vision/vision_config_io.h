#pragma once

#include <opencv2/core/persistence.hpp>
#include <string>

#include "vision/vision_pipeline.h"

namespace houghloc {

/// Reads the `vision:` section of a config file (DESIGN §2): one sub-map per VisionConfig member
/// (horizon, field_color, boundary, line_width, scan_grid, spots, projection, segments,
/// pose_correction) whose keys equal the struct members; missing keys keep their defaults.
/// Throws std::runtime_error naming `source` and the key for unknown keys or wrong types.
VisionConfig readVisionConfig(const cv::FileNode& section, const std::string& source);

/// Writes `config` as a `vision` section (for --print-config and round trips).
void writeVisionConfig(cv::FileStorage& storage, const VisionConfig& config);

}  // namespace houghloc
