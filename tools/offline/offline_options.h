#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace houghloc {

/// The houghloc-offline command line (DESIGN §5.2, docs/offline.md).
struct OfflineOptions {
  std::string folder;   ///< required unless --print-config or --lcm-log
  std::string out_dir;  ///< default FOLDER/houghloc/
  std::string field_file;
  std::string standard;
  std::string config_file;
  std::string video_file;  ///< --video: the overlays as a video (.mp4: mp4v, .avi: MJPG)
  bool vision_only = false;
  bool global_only = false;
  bool overlay = false;
  bool points = false;
  bool quiet = false;
  bool evaluate_only = false;
  bool print_config = false;
  bool learn_tilt_first = false;  ///< vision over the frame range once first (camera tilt)
  int start = 0;                  ///< first frame index
  int end = -1;                   ///< one past the last frame index; -1 = all
  int threads = 1;                ///< 2: vision of frame k+1 overlaps localization of frame k
  std::string lcm_log;            ///< --lcm-log: an lcm-logger log instead of FOLDER
  std::vector<std::string> camera_yamls;  ///< with --lcm-log: [ID=]camera.yaml per camera
  std::string channel_prefix;             ///< with --lcm-log: the node's --channel-prefix
};

enum class OfflineMode { kVisionOnly, kGlobalOnly, kFull };

/// Registers the options on `app` (CLI11).
void addOfflineOptions(CLI::App& app, OfflineOptions* options);

OfflineMode offlineMode(const OfflineOptions& options);

}  // namespace houghloc
