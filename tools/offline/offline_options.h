#pragma once

#include <string>

namespace CLI {
class App;
}

namespace houghloc {

/// The houghloc-offline command line (DESIGN §5.2).
struct OfflineOptions {
  std::string folder;
  std::string out_dir;  ///< default FOLDER/houghloc/
  std::string field_file;
  std::string standard;
  std::string config_file;
  bool vision_only = false;
  bool global_only = false;
  bool overlay = false;
  bool points = false;
  bool quiet = false;
  bool evaluate_only = false;
  int start = 0;  ///< first frame index
  int end = -1;   ///< one past the last frame index; -1 = all
};

enum class OfflineMode { kVisionOnly, kGlobalOnly, kFull };

/// Registers the options on `app` (CLI11).
void addOfflineOptions(CLI::App& app, OfflineOptions* options);

OfflineMode offlineMode(const OfflineOptions& options);

}  // namespace houghloc
