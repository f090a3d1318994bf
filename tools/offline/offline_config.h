#pragma once

#include <opencv2/core/persistence.hpp>
#include <string>

#include "localization/localizer.h"
#include "vision/vision_pipeline.h"

namespace houghloc {

/// The sections of a houghloc config file (DESIGN §2) that houghloc-offline uses.
struct OfflineConfig {
  VisionConfig vision;        ///< `vision:`
  LocalizerConfig localizer;  ///< `global:`, `tracker:`, `localizer:`
};

/// Opens a houghloc config file for reading (every tool's sections are in the one file): the
/// "%YAML:1.0" line is optional, and the text passes checkYamlBeforeFileStorage() first.
/// Throws std::runtime_error naming the file.
cv::FileStorage openConfigFile(const std::string& path);

/// Reads a config file; a missing section or key keeps its default. An empty path gives the
/// defaults. Throws std::runtime_error naming the file (and key) at fault.
OfflineConfig loadOfflineConfig(const std::string& path);

/// The defaults of every section as a YAML config file (--print-config); loadOfflineConfig()
/// of this text gives the defaults back.
std::string defaultConfigYaml();

}  // namespace houghloc
