#include "global_accuracy_fixture.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <ctime>
#include <random>
#include <sstream>

#include "field_models/standard_fields.h"
#include "localization/global_hough_localizer.h"
#include "tools/baselines/grid_search.h"
#include "tools/offline/evaluation_frames.h"
#include "tools/synthetic/synthetic_ground_points.h"

namespace houghloc {
namespace {

double cpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/// Frame k of a run: random pose, every third frame with an occluding robot, 5% outliers.
SyntheticFrame makeFrame(const FieldModel& field, const AccuracyRun& run, std::mt19937_64& rng,
                         int k) {
  SyntheticConfig config;
  config.view = viewModel(run.view);
  config.seed = run.seed * 7919 + k;
  config.occluders = k % 3 == 0 ? 1 : 0;
  return generateFrame(field, randomPose(field, 0.3, rng), config);
}

}  // namespace

std::string AccuracySummary::describe(const std::string& label) const {
  std::ostringstream s;
  s.precision(3);
  s << label << ": " << frames << " frames, GHL any " << rate(ghl_any) << "% top1 "
    << rate(ghl_top1) << "% top2 " << rate(ghl_top2) << "%";
  if (ghl_positive_any > 0) s << " (positive-only " << rate(ghl_positive_any) << "%)";
  s << ", median " << 100.0 * median(position_errors_m) << " cm "
    << median(heading_errors_rad) * 180.0 / M_PI << " deg, "
    << 1000.0 * ghl_seconds / std::max(1, frames) << " ms/frame";
  if (grid_seconds > 0.0) {
    s << " | grid any " << rate(grid_any) << "% top1 " << rate(grid_top1) << "%, "
      << 1000.0 * grid_seconds / std::max(1, frames) << " ms/frame";
  }
  return s.str();
}

AccuracySummary evaluateGlobal(const AccuracyRun& run) {
  const FieldModel field = makeStandardField(run.field);
  const GlobalHoughLocalizer ghl(field);
  GlobalHoughConfig positive_config;
  positive_config.negative.enabled = false;
  const GlobalHoughLocalizer positive(field, positive_config);
  const GridSearchLocalizer grid(field);
  std::mt19937_64 rng(run.seed);
  AccuracySummary out;
  for (int k = 0; out.frames < run.frames && k < 300 * run.frames; ++k) {
    const SyntheticFrame f = makeFrame(field, run, rng, k);
    if (!hasTwoDirections(f)) continue;
    ++out.frames;
    const double t0 = cpuSeconds();
    const auto hs = ghl.locate(f.ground);
    out.ghl_seconds += cpuSeconds() - t0;
    std::vector<Pose2> poses;
    for (const auto& h : hs) poses.push_back(h.field_T_robot);
    const CorrectRank rank = correctRankUpToSymmetry(poses, f.field_T_robot);
    if (rank.index >= 0) {
      ++out.ghl_any;
      out.ghl_top1 += rank.index == 0;
      out.ghl_top2 += rank.answer <= 1;
      const PoseError e = symmetricPoseError(poses[rank.index], f.field_T_robot);
      out.position_errors_m.push_back(e.position_m);
      out.heading_errors_rad.push_back(e.heading_rad);
    }
    if (run.positive_only) {
      poses.clear();
      for (const auto& h : positive.locate(f.ground)) poses.push_back(h.field_T_robot);
      out.ghl_positive_any += correctRankUpToSymmetry(poses, f.field_T_robot).index >= 0;
    }
    if (run.grid) {
      const double t1 = cpuSeconds();
      const auto optima = grid.locate(f.ground);
      out.grid_seconds += cpuSeconds() - t1;
      poses.clear();
      for (const auto& o : optima) poses.push_back(o.field_T_robot);
      const CorrectRank grid_rank = correctRankUpToSymmetry(poses, f.field_T_robot);
      out.grid_any += grid_rank.index >= 0;
      out.grid_top1 += grid_rank.index == 0;
    }
  }
  return out;
}

ParallelSummary evaluateParallelOnly(const AccuracyRun& run) {
  const FieldModel field = makeStandardField(run.field);
  const GlobalHoughLocalizer ghl(field);
  std::mt19937_64 rng(run.seed);
  ParallelSummary out;
  for (int k = 0; out.frames < run.frames && k < 200 * run.frames; ++k) {
    const SyntheticFrame f = makeFrame(field, run, rng, k);
    if (!hasOnlyParallelLines(f)) continue;
    ++out.frames;
    const Pose2& truth = f.field_T_robot;
    bool within = false;
    for (const auto& h : ghl.locate(f.ground)) {
      if (h.kind != HypothesisKind::kParallel) continue;
      for (const Pose2& t : {truth, Pose2(-truth.x, -truth.y, truth.theta + M_PI)}) {
        const Eigen::Vector3d d(t.x - h.field_T_robot.x, t.y - h.field_T_robot.y,
                                angleDifference(t.theta, h.field_T_robot.theta));
        within |= d.dot(h.covariance.ldlt().solve(d)) <= 9.0;
      }
    }
    out.within += within;
  }
  return out;
}

}  // namespace houghloc
