// houghloc-offline: runs the pipeline on a recorded image folder (DESIGN §5.2,
// docs/offline.md).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "tools/offline/evaluate_only.h"
#include "tools/offline/lcm_log_mode.h"
#include "tools/offline/mode_full.h"
#include "tools/offline/mode_global_only.h"
#include "tools/offline/mode_vision_only.h"
#include "tools/offline/offline_config.h"
#include "tools/offline/offline_context.h"
#include "tools/offline/offline_options.h"

int main(int argc, char** argv) {
  using namespace houghloc;
  CLI::App app{
      "houghloc-offline: runs houghloc on a recorded image folder (DESIGN 5.2) or on an "
      "lcm-logger log of houghloc-node (--lcm-log)"};
  OfflineOptions options;
  addOfflineOptions(app, &options);
  CLI11_PARSE(app, argc, argv);

  try {
    if (options.print_config) {
      std::fputs(defaultConfigYaml().c_str(), stdout);
      return 0;
    }
    if (!options.lcm_log.empty()) return runLcmLog(options);
    if (!options.camera_yamls.empty() || !options.channel_prefix.empty()) {
      std::fprintf(stderr, "houghloc-offline: --camera-yaml and --channel-prefix need --lcm-log\n");
      return 2;
    }
    if (options.folder.empty()) {
      std::fprintf(stderr, "FOLDER is required\nRun with --help for more information.\n");
      return 106;  // CLI11's exit code for a missing required argument
    }
    const OfflineMode mode = offlineMode(options);
    if (mode == OfflineMode::kVisionOnly && !options.video_file.empty()) {
      std::fprintf(stderr, "houghloc-offline: --video needs a localization mode\n");
      return 2;
    }
    const OfflineContext context = loadOfflineContext(options);
    if (options.evaluate_only) return runEvaluateOnly(context, mode == OfflineMode::kGlobalOnly);
    switch (mode) {
      case OfflineMode::kVisionOnly:
        return runVisionOnly(context);
      case OfflineMode::kGlobalOnly:
        return runGlobalOnly(context);
      case OfflineMode::kFull:
        return runFull(context);
    }
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "houghloc-offline: error: %s\n", e.what());
    return 2;
  }
}
