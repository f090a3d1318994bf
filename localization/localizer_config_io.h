#pragma once

#include <opencv2/core/persistence.hpp>
#include <string>

#include "localization/localizer.h"

namespace houghloc {

/// Reads the localization sections of a config file (DESIGN §2): `global:` (GlobalHoughConfig),
/// `tracker:` (TrackerConfig) and `localizer:` (the LocalizerConfig members of its own), each
/// with one sub-map per nested config struct whose keys equal the member names. A section or key
/// that is missing keeps its default. `root` is the file's top-level map. Throws
/// std::runtime_error naming `source` and the key for unknown keys or wrong types.
LocalizerConfig readLocalizerConfig(const cv::FileNode& root, const std::string& source);

/// Writes `config` as the `global`, `tracker` and `localizer` sections (for --print-config and
/// round trips: readLocalizerConfig(written) == config).
void writeLocalizerConfig(cv::FileStorage& storage, const LocalizerConfig& config);

}  // namespace houghloc
