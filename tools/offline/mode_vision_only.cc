#include "tools/offline/mode_vision_only.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "tools/offline/correction_summary.h"
#include "tools/offline/offline_output.h"
#include "tools/offline/overlay.h"
#include "tools/offline/vision_metrics.h"
#include "tools/offline/vision_stage.h"
#include "tools/recording/csv.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

struct RunStats {
  int processed = 0, skipped = 0, scored = 0;
  long points = 0;
  double total_ms = 0.0, max_ms = 0.0;
  CorrectionSummary corrections;
};

void printSummary(const RunStats& s, const std::optional<VisionMetrics>& metrics,
                  const std::string& out_dir) {
  std::printf("houghloc-offline --vision-only -> %s\n", out_dir.c_str());
  std::printf("  frames processed %d, skipped %d (missing/unreadable images), scored %d\n",
              s.processed, s.skipped, s.scored);
  if (s.processed > 0) {
    std::printf("  points/frame %.1f   vision time mean %.3f ms, max %.3f ms\n",
                static_cast<double>(s.points) / s.processed, s.total_ms / s.processed, s.max_ms);
  }
  s.corrections.print();
  if (!metrics) {
    std::printf("  no metrics (needs groundtruth.csv, truth/visible.csv and a field)\n");
    return;
  }
  std::printf("  precision %.4f over %ld points\n", metrics->precision, metrics->points);
  std::printf("  %-9s %8s %10s %8s %12s %12s\n", "band", "points", "precision", "recall",
              "median err", "p95 err");
  for (const VisionBandMetrics& b : metrics->bands) {
    std::printf("  %.0f-%.0f m    %8ld %10.4f %8.4f %10.4f m %10.4f m\n", b.min_m, b.max_m,
                b.points, b.precision, b.recall, b.median_error_m, b.p95_error_m);
  }
  const FieldEdgeMetrics& e = metrics->field_edge;
  if (e.samples > 0) {
    std::printf(
        "  field edge: %ld samples, median error %.3f m (%.2f sigma), within 3 sigma %.3f, "
        "nearer %.3f, farther %.3f\n",
        e.samples, e.median_abs_error_m, e.median_abs_error_sigmas, e.within_3_sigma,
        e.nearer_share, e.farther_share);
  }
}

}  // namespace

int runVisionOnly(const OfflineContext& context) {
  const Recording& rec = context.recording;
  const fs::path out(context.out_dir);
  CsvWriter points_csv((out / "points.csv").string(), {"t_us", "u", "v", "x_robot", "y_robot"});
  CsvWriter timing_csv((out / "timing.csv").string(), {"t_us", "vision_ms", "points"});
  if (context.options.overlay) fs::create_directories(out / "overlay");

  const bool can_score = context.field && !rec.ground_truth.empty() && !rec.visible.empty();
  std::optional<VisionMetricsAccumulator> metrics;
  if (can_score) metrics.emplace(*context.field);

  RunStats stats;
  const int total = context.end_frame - context.first_frame;
  // Same loading and per-camera pipelines as the localization modes (tools/offline/vision_stage).
  const auto pipeline = makePipeline(context, PipelineMode::kVisionOnly);
  runVisionStage(
      context, *pipeline, context.options.threads, context.options.overlay, [&](VisionFrame& v) {
        if (v.skipped) {
          std::fprintf(stderr, "%swarning: %s\n", context.options.quiet ? "" : "\n",
                       v.problem.c_str());
          ++stats.skipped;
          return;
        }
        const FrameRecord& frame = *v.frame;
        const VisionResult& result = v.seen.vision;
        ++stats.processed;
        stats.points += static_cast<long>(result.ground.points.size());
        stats.total_ms += result.diagnostics.time_total_ms;
        stats.max_ms = std::max(stats.max_ms, result.diagnostics.time_total_ms);
        stats.corrections.add(frame.camera_id, result.diagnostics);
        for (const GroundPoint& p : result.ground.points) {
          points_csv.writeRow({points_csv.format(frame.t_us), points_csv.format(p.pixel.x()),
                               points_csv.format(p.pixel.y()), points_csv.format(p.p_robot.x()),
                               points_csv.format(p.p_robot.y())});
        }
        timing_csv.writeRow(
            {points_csv.format(frame.t_us), timing_csv.format(result.diagnostics.time_total_ms),
             timing_csv.format(static_cast<std::int64_t>(result.ground.points.size()))});
        if (metrics) {
          if (const auto truth = groundTruthAt(rec.ground_truth, frame.t_us)) {
            // Visibility is judged from the recorded pose, as the ground truth was rendered.
            const CameraModel camera(*v.intrinsics, frame.robot_T_camera);
            metrics->addFrame(result.ground, *truth, visibleAt(rec.visible, frame.t_us), camera);
            ++stats.scored;
          }
        }
        if (v.image) {
          const std::string name = fs::path(frame.image).stem().string() + ".png";
          const CameraModel camera(*v.intrinsics, result.robot_T_camera_used);
          cv::imwrite((out / "overlay" / name).string(),
                      drawVisionOverlay(*v.image, result, camera));
        }
        reportProgress(context, "vision", v.index - context.first_frame + 1, total);
      });
  points_csv.close();
  timing_csv.close();
  std::optional<VisionMetrics> summary;
  if (metrics && stats.scored > 0) {
    summary = metrics->result();
    writeMetricsSection(context.out_dir, "vision", toJson(*summary));
  }
  printSummary(stats, summary, context.out_dir);
  return 0;
}

}  // namespace houghloc
