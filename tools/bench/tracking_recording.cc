#include "tools/bench/tracking_recording.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>

#include "field_models/distance_grid.h"
#include "tools/bench/mcl_baseline.h"
#include "tools/offline/localization_run.h"
#include "tools/offline/mode_full.h"
#include "tools/offline/vision_stage.h"

namespace houghloc::bench {

double cpuNowUs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e6 * static_cast<double>(t.tv_sec) + 1e-3 * static_cast<double>(t.tv_nsec);
}

RecordedRun loadRecordedRun(const std::string& dir) {
  OfflineOptions options;
  options.folder = dir;
  options.quiet = true;
  options.out_dir = (std::filesystem::temp_directory_path() / "houghloc-bench-tracking").string();
  RecordedRun run{loadOfflineContext(options), {}, 0.0};
  requireField(run.context);
  run.points.reserve(run.context.end_frame - run.context.first_frame);
  const auto vision = makePipeline(run.context, PipelineMode::kVisionOnly);
  runVisionStage(run.context, *vision, 1, false, [&](VisionFrame& v) {
    run.points.push_back(std::move(v.seen.vision.ground));
    run.mean_points += static_cast<double>(run.points.back().size());
  });
  if (!run.points.empty()) run.mean_points /= static_cast<double>(run.points.size());
  return run;
}

RunOutput runLocalizer(const RecordedRun& run) {
  const OfflineContext& context = run.context;
  // The localization half of houghloc-offline's full mode on the points computed once.
  const auto pipeline = makePipeline(context, PipelineMode::kFull);
  RunOutput out;
  for (size_t k = 0; k < run.points.size(); ++k) {
    const FrameRecord& frame = context.recording.frames[context.first_frame + k];
    SeenFrame seen;
    seen.frame = {frame.t_us, frame.camera_id, frame.robot_T_camera, frame.odometry};
    seen.sequence = static_cast<int>(k);
    seen.has_image = true;
    seen.vision.ground = run.points[k];
    const double t0 = cpuNowUs();  // the hints due are applied and timed with the frame
    const LocalizationEstimate estimate = pipeline->locate(seen).estimate;
    out.cpu_us.push_back(cpuNowUs() - t0);
    out.estimates.push_back(toFrameEstimate(frame.t_us, estimate));
  }
  return out;
}

RunOutput runMcl(const RecordedRun& run, std::uint32_t seed) {
  const OfflineContext& context = run.context;
  const DistanceGrid grid(*context.field);
  MonteCarloLocalizer mcl(*context.field, grid, MclConfig{}, seed);
  RunOutput out;
  size_t next_hint = 0;
  bool started = false;  // a hint or the uniform start has placed the particles
  for (size_t k = 0; k < run.points.size(); ++k) {
    const int index = context.first_frame + static_cast<int>(k);
    const FrameRecord& frame = context.recording.frames[index];
    const double t0 = cpuNowUs();
    while (next_hint < context.hints.size() && context.hints[next_hint].t_us <= frame.t_us) {
      const LocalizationHint& hint = context.hints[next_hint++];
      if (hint.kind != HintKind::kResetTo || hint.poses.empty()) continue;
      const Eigen::Matrix3d& cov = hint.poses.front().covariance;
      mcl.reset(hint.poses.front().mean, std::sqrt(0.5 * (cov(0, 0) + cov(1, 1))),
                std::sqrt(cov(2, 2)));
      started = true;
    }
    if (!started) {  // no start hint: a global start from particles all over the field
      mcl.resetUniform();
      started = true;
    }
    // Robot-frame motion since the previous frame; none on the first one or next to a frame
    // without odometry (the benchmark recordings have odometry in every frame).
    const std::optional<Pose2>& previous =
        context.recording.frames[std::max(index - 1, 0)].odometry;
    const Pose2 motion =
        k == 0 || !previous || !frame.odometry ? Pose2() : previous->inverse() * *frame.odometry;
    mcl.update(motion, run.points[k]);
    out.cpu_us.push_back(cpuNowUs() - t0);
    FrameEstimate e;
    e.t_us = frame.t_us;
    e.status = "TRACKING";
    GaussianPose g;
    g.mean = mcl.estimate();
    g.covariance = mcl.covariance();
    g.weight = 1.0;
    e.hypotheses.push_back(g);
    out.estimates.push_back(std::move(e));
  }
  return out;
}

}  // namespace houghloc::bench
