// houghloc-offline: runs the pipeline on a recorded image folder (DESIGN §5.2).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "tools/offline/mode_vision_only.h"
#include "tools/offline/offline_context.h"
#include "tools/offline/offline_options.h"

int main(int argc, char** argv) {
  using namespace houghloc;
  CLI::App app{"houghloc-offline: runs houghloc on a recorded image folder (DESIGN 5.2)"};
  OfflineOptions options;
  addOfflineOptions(app, &options);
  CLI11_PARSE(app, argc, argv);

  const OfflineMode mode = offlineMode(options);
  if (mode != OfflineMode::kVisionOnly || options.evaluate_only) {
    const char* what = options.evaluate_only              ? "--evaluate-only"
                       : mode == OfflineMode::kGlobalOnly ? "--global-only"
                                                          : "the full mode (tracking)";
    std::fprintf(stderr,
                 "houghloc-offline: %s is not implemented yet in this build; "
                 "use --vision-only\n",
                 what);
    return 3;
  }
  try {
    const OfflineContext context = loadOfflineContext(options);
    return runVisionOnly(context);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "houghloc-offline: error: %s\n", e.what());
    return 2;
  }
}
