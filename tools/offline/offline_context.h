#pragma once

#include <optional>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "localization/localization_hint.h"
#include "localization/localizer.h"
#include "tools/offline/offline_options.h"
#include "tools/recording/recording.h"
#include "vision/vision_pipeline.h"

namespace houghloc {

/// Everything a mode needs, loaded and checked before any frame runs.
struct OfflineContext {
  OfflineOptions options;
  Recording recording;
  std::optional<FieldModel> field;      ///< --field, --standard, or FOLDER/field.yaml
  VisionConfig vision_config;           ///< defaults, then the --config file (the pipeline takes line width and circle from the map)
  LocalizerConfig localizer_config;     ///< defaults, then the --config file
  std::vector<LocalizationHint> hints;  ///< hints.csv, in time order
  std::string out_dir;                  ///< exists and is writable
  int first_frame = 0, end_frame = 0;
};

/// Reads the folder, the field and the config and prepares the output folder. Throws
/// std::runtime_error (or RecordingError) whose message names the file (and line or key) at fault.
OfflineContext loadOfflineContext(const OfflineOptions& options);

/// Creates `dir` when missing and checks that it is writable; throws std::runtime_error naming it.
void prepareOutputFolder(const std::string& dir);

}  // namespace houghloc
