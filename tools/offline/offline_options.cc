#include "tools/offline/offline_options.h"

#include <CLI/CLI.hpp>

namespace houghloc {

void addOfflineOptions(CLI::App& app, OfflineOptions* o) {
  app.add_option("FOLDER", o->folder, "recorded image folder (DESIGN 5.1)")->required();
  app.add_option("-o,--out", o->out_dir, "output folder (default FOLDER/houghloc/)");
  auto* field = app.add_option("--field", o->field_file, "field map YAML");
  app.add_option("--standard", o->standard, "standard field: spl, spl2019, kid, adult, msl")
      ->excludes(field);
  app.add_option("--config", o->config_file, "config YAML with a vision: section (and others)");
  auto* vision =
      app.add_flag("--vision-only", o->vision_only, "run vision alone, write points.csv");
  app.add_flag("--global-only", o->global_only, "vision + global localization per frame")
      ->excludes(vision);
  app.add_flag("--overlay", o->overlay, "draw points, boundary and horizon into OUT/overlay/");
  app.add_flag("--points", o->points, "write points.csv");
  app.add_flag("--quiet", o->quiet, "no progress output");
  app.add_option("--start", o->start, "first frame index")->check(CLI::NonNegativeNumber);
  app.add_option("--end", o->end, "one past the last frame index (default: all)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--evaluate-only", o->evaluate_only,
               "recompute metrics from the files already in OUT (later issue)");
}

OfflineMode offlineMode(const OfflineOptions& o) {
  if (o.vision_only) return OfflineMode::kVisionOnly;
  if (o.global_only) return OfflineMode::kGlobalOnly;
  return OfflineMode::kFull;
}

}  // namespace houghloc
