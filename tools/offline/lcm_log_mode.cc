#include "tools/offline/lcm_log_mode.h"

#include <cstdio>
#include <optional>
#include <stdexcept>

#include "tools/node/node_options.h"
#include "tools/offline/lcm_log_replay.h"
#include "tools/offline/localization_evaluation.h"
#include "tools/offline/offline_config.h"
#include "tools/offline/progress.h"
#include "tools/offline/run_field.h"

namespace houghloc {
namespace {

/// The folder-only options, rejected with --lcm-log (the node runs the full mode only).
void rejectFolderOptions(const OfflineOptions& o) {
  auto reject = [](bool given, const char* name) {
    if (given) throw std::runtime_error(std::string(name) + " cannot be combined with --lcm-log");
  };
  reject(!o.folder.empty(), "FOLDER");
  reject(o.vision_only, "--vision-only");
  reject(o.global_only, "--global-only");
  reject(o.overlay, "--overlay");
  reject(!o.video_file.empty(), "--video");
  reject(o.points, "--points");
  reject(o.evaluate_only, "--evaluate-only");
  reject(o.start != 0 || o.end != -1, "--start/--end");
  reject(o.threads != 1, "--threads");
  if (o.camera_yamls.empty())
    throw std::runtime_error("--lcm-log needs --camera-yaml [ID=]FILE for every camera");
  if (o.field_file.empty() == o.standard.empty())
    throw std::runtime_error("--lcm-log needs --field FILE or --standard NAME (the node's)");
}

void printSummary(const std::string& out_dir, const LogReplayResult& r) {
  std::printf("houghloc-offline --lcm-log -> %s\n", out_dir.c_str());
  std::printf("  images in the log        %d (%d HYPOTHESES logged)\n", r.images,
              r.logged_hypotheses);
  std::printf("  images processed         %zu\n", r.estimates.size());
  std::printf("  max difference to log    %.3g (status or count differs on %d)\n", r.max_difference,
              r.mismatches);
}

}  // namespace

int runLcmLog(const OfflineOptions& options) {
  rejectFolderOptions(options);
  LogReplayInput input;
  input.log_path = options.lcm_log;
  input.channel_prefix = options.channel_prefix;
  const FieldModel field = loadRunField(options.field_file, options.standard);
  input.field = std::make_shared<const FieldModel>(field);
  // As houghloc-node composes its PipelineConfig from the same config file.
  const OfflineConfig loaded = loadOfflineConfig(options.config_file);
  input.config.vision = loaded.vision;
  input.config.localizer = loaded.localizer;
  if (!options.config_file.empty()) {
    input.static_camera_poses = readStaticCameraPoses(options.config_file);
    input.config_file = options.config_file;
  }
  for (const std::string& arg : options.camera_yamls) {
    const auto eq = arg.find('=');
    const std::string id = eq == std::string::npos ? "" : arg.substr(0, eq);
    input.cameras[id] = loadCameraYaml(eq == std::string::npos ? arg : arg.substr(eq + 1));
  }

  OfflineContext context;  // what the folder modes' evaluation needs, filled from the log
  context.options = options;
  context.options.folder = options.lcm_log;
  context.out_dir = options.out_dir.empty() ? options.lcm_log + ".houghloc" : options.out_dir;
  prepareOutputFolder(context.out_dir);
  context.field = field;

  std::optional<ProgressReporter> progress;
  LogReplayResult result = replayLcmLog(input, [&](int done, int total) {
    if (!progress) progress.emplace("lcm-log", total, options.quiet);
    progress->update(done);
  });
  if (progress) progress->finish();
  if (result.truncated_at >= 0) {
    std::fprintf(stderr, "houghloc-offline: %s: last event cut short at byte %lld; ignored\n",
                 options.lcm_log.c_str(), static_cast<long long>(result.truncated_at));
  }
  if (result.refused > 0) {
    std::fprintf(stderr,
                 "houghloc-offline: %d image(s) with logged HYPOTHESES refused here (first: %s); "
                 "are --camera-yaml and --channel-prefix the node's?\n",
                 result.refused, result.first_refusal.c_str());
  }
  if (result.logged_hypotheses == 0) {
    throw std::runtime_error(options.lcm_log + ": no " + options.channel_prefix +
                             "HYPOTHESES messages (wrong --channel-prefix?)");
  }
  {
    EstimateCsvWriter writer(context.out_dir);
    for (const FrameEstimate& e : result.estimates) writer.write(e);
    writer.close();
  }
  context.recording.folder = options.lcm_log;
  context.recording.frames = std::move(result.frames);
  context.recording.ground_truth = std::move(result.ground_truth);
  context.end_frame = static_cast<int>(context.recording.frames.size());
  const EvaluationResult evaluation = evaluateOutputs(context, false);
  printSummary(context.out_dir, result);
  printEvaluation(evaluation);
  return 0;
}

}  // namespace houghloc
