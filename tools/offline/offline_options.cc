#include "tools/offline/offline_options.h"

#include <CLI/CLI.hpp>

namespace houghloc {

void addOfflineOptions(CLI::App& app, OfflineOptions* o) {
  // Not ->required(): --print-config needs no folder; main() checks it.
  app.add_option("FOLDER", o->folder, "recorded image folder (DESIGN 5.1)");
  app.add_option("-o,--out", o->out_dir, "output folder (default FOLDER/houghloc/)");
  auto* field = app.add_option("--field", o->field_file, "field map YAML");
  app.add_option("--standard", o->standard, "standard field: spl, spl2019, kid, adult, msl")
      ->excludes(field);
  app.add_option("--config", o->config_file,
                 "config YAML with vision:, global:, tracker:, localizer: sections");
  app.add_flag("--print-config", o->print_config,
               "write the default config (every section) to stdout and exit");
  auto* vision =
      app.add_flag("--vision-only", o->vision_only, "run vision alone, write points.csv");
  app.add_flag("--global-only", o->global_only, "vision + global localization per frame")
      ->excludes(vision);
  app.add_flag("--overlay", o->overlay, "one overlay image per frame in OUT/overlay/");
  app.add_option("--video", o->video_file,
                 "write the overlays as a video (.mp4: mp4v codec, .avi: MJPG)");
  app.add_flag("--points", o->points, "write points.csv");
  app.add_flag("--quiet", o->quiet, "no progress output");
  app.add_option("--start", o->start, "first frame index")->check(CLI::NonNegativeNumber);
  app.add_option("--end", o->end, "one past the last frame index (default: all)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--threads", o->threads,
                 "1, or 2: vision of the next frame overlaps localization (same results)")
      ->check(CLI::Range(1, 2));
  app.add_flag("--evaluate-only", o->evaluate_only,
               "recompute metrics.json and trajectory.png from poses.csv/hypotheses.csv in OUT "
               "(with --global-only: of a --global-only run)")
      ->excludes(vision);
  auto* learn_tilt = app.add_flag(
      "--learn-tilt-first", o->learn_tilt_first,
      "run the vision over the frames once before the run, so that every frame starts from what "
      "all of them say about the camera's pitch and roll error (stills from one robot, or a "
      "recording whose camera pose is off from its first frame)");
  app.add_option("--lcm-log", o->lcm_log,
                 "run on an lcm-logger log of houghloc-node instead of FOLDER: the images the node "
                 "answered with HYPOTHESES (needs --camera-yaml and --field or --standard)")
      ->excludes(learn_tilt);
  app.add_option("--camera-yaml", o->camera_yamls,
                 "with --lcm-log: [ID=]camera.yaml, one per camera (no ID: the camera '')");
  app.add_option("--channel-prefix", o->channel_prefix, "with --lcm-log: the node's prefix");
}

OfflineMode offlineMode(const OfflineOptions& o) {
  if (o.vision_only) return OfflineMode::kVisionOnly;
  if (o.global_only) return OfflineMode::kGlobalOnly;
  return OfflineMode::kFull;
}

}  // namespace houghloc
