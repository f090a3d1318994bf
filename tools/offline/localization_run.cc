#include "tools/offline/localization_run.h"

#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "tools/offline/localization_evaluation.h"
#include "tools/offline/localization_overlay.h"
#include "tools/offline/overlay_sink.h"
#include "tools/offline/progress.h"
#include "tools/offline/run_summary.h"
#include "tools/recording/csv.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kTimingHeader = {"t_us",      "vision_ms", "localization_ms",
                                                "global_ms", "points",    "hypotheses",
                                                "load_ms",   "skipped"};

void writePoints(CsvWriter* csv, const VisionFrame& v) {
  for (const GroundPoint& p : v.seen.vision.ground.points) {
    csv->writeRow({csv->format(v.frame->t_us), csv->format(p.pixel.x()), csv->format(p.pixel.y()),
                   csv->format(p.p_robot.x()), csv->format(p.p_robot.y())});
  }
}

cv::Mat overlayFor(const OfflineContext& context, const VisionFrame& v,
                   const FrameEstimate& estimate) {
  if (!v.image) {
    return drawMissingFrameOverlay(v.intrinsics->image_width, v.intrinsics->image_height, v.problem,
                                   estimate);
  }
  const CameraModel camera(*v.intrinsics, v.seen.vision.robot_T_camera_used);
  return drawLocalizationOverlay(*v.image, v.seen.vision, camera, *context.field, estimate,
                                 groundTruthAt(context.recording.ground_truth, v.frame->t_us));
}

}  // namespace

const FieldModel& requireField(const OfflineContext& context) {
  if (!context.field) {
    throw std::runtime_error(context.options.folder +
                             ": no field map (give --field FILE or --standard NAME, or put "
                             "field.yaml into the folder)");
  }
  return *context.field;
}

int runLocalizationMode(const OfflineContext& context, LocalizationPipeline& pipeline,
                        const std::string& title, bool global_only, const LocalizationStep& step) {
  requireField(context);
  const auto wall_start = std::chrono::steady_clock::now();
  const fs::path out(context.out_dir);
  EstimateCsvWriter estimates(context.out_dir);
  CsvWriter timing((out / "timing.csv").string(), kTimingHeader);
  std::unique_ptr<CsvWriter> points;
  if (context.options.points) {
    points = std::make_unique<CsvWriter>(
        (out / "points.csv").string(),
        std::vector<std::string>{"t_us", "u", "v", "x_robot", "y_robot"});
  }
  OverlaySink overlays(context);
  ProgressReporter progress(global_only ? "global" : "localization",
                            context.end_frame - context.first_frame, context.options.quiet);
  RunStats stats;
  int done = 0;
  runVisionStage(
      context, pipeline, context.options.threads, overlays.active(), [&](VisionFrame& v) {
        if (v.skipped) {
          progress.warn(v.problem);
          ++stats.skipped;
        } else {
          ++stats.processed;
        }
        const LocalizationStepResult r = step(v);
        estimates.write(r.estimate);
        if (points) writePoints(points.get(), v);
        const auto n = static_cast<std::int64_t>(v.seen.vision.ground.points.size());
        timing.writeRow({timing.format(v.frame->t_us), timing.format(v.vision_ms),
                         timing.format(r.localization_ms), timing.format(r.global_ms),
                         timing.format(n),
                         timing.format(static_cast<std::int64_t>(r.estimate.hypotheses.size())),
                         timing.format(v.load_ms), v.skipped ? "1" : "0"});
        stats.points += n;
        stats.load_ms.push_back(v.load_ms);
        if (!v.skipped) {
          stats.vision_ms.push_back(v.vision_ms);
          stats.corrections.add(v.frame->camera_id, v.seen.vision.diagnostics);
        }
        stats.localization_ms.push_back(r.localization_ms);
        stats.global_ms.push_back(r.global_ran ? r.global_ms : 0.0);
        if (r.global_ran) ++stats.global_runs;
        stats.total_ms.push_back(v.load_ms + v.vision_ms + r.localization_ms);
        ++stats.status_counts[r.estimate.status];
        if (overlays.active()) overlays.write(*v.frame, overlayFor(context, v, r.estimate));
        progress.update(++done);
      });
  progress.finish();
  estimates.close();
  timing.close();
  if (points) points->close();
  overlays.close();
  const EvaluationResult evaluation = evaluateOutputs(context, global_only);
  stats.wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  printRunSummary(title + " -> " + context.out_dir, stats, context.options.threads);
  printEvaluation(evaluation);
  return 0;
}

}  // namespace houghloc
