#include "tools/realframes/groundtruth_report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace houghloc {
namespace {

std::string stem(const std::string& image) { return std::filesystem::path(image).stem().string(); }

}  // namespace

PooledCoverage pooledCoverage(const std::vector<GroundTruthFrameReport>& frames) {
  PooledCoverage pooled;
  for (const GroundTruthFrameReport& f : frames) {
    pooled.visible += f.houghloc.visible_samples;
    pooled.covered += f.houghloc.covered_samples;
    pooled.baseline_covered += f.baseline.covered_samples;
  }
  return pooled;
}

void printGroundTruthFrames(const std::vector<GroundTruthFrameReport>& frames) {
  std::printf(
      "\nframes with lines and a ground-truth pose (recorded camera pose; median: point to "
      "nearest map feature; beyond: share > 0.1 m beyond a goal line; cover: share of the map's "
      "line samples within 5 m in view with a point within 0.15 m)\n");
  std::printf("%-28s | %6s %7s %6s %6s | %8s %7s %6s %6s\n", "frame", "points", "median", "beyond",
              "cover", "base-pts", "median", "beyond", "cover");
  for (const GroundTruthFrameReport& f : frames) {
    const GroundTruthMetrics& h = f.houghloc;
    const GroundTruthMetrics& b = f.baseline;
    std::printf("%-28s | %6d %7.3f %6.3f %6.3f | %8d %7.3f %6.3f %6.3f\n", stem(f.image).c_str(),
                h.points, h.median_distance_m, h.beyond_goal_share, h.coverage, b.points,
                b.median_distance_m, b.beyond_goal_share, b.coverage);
  }
  const PooledCoverage all = pooledCoverage(frames);
  if (all.visible > 0) {
    std::printf("all %zu frames: cover %.3f (%ld of %ld samples), baseline %.3f\n", frames.size(),
                all.share(), all.covered, all.visible, all.baselineShare());
  }
}

void printGlobalCheck(const char* title, const std::vector<GlobalCheckFrame>& frames) {
  std::printf(
      "\n--global-only at the ground truth, %s (hit: a hypothesis within 0.15 m and 5 deg)\n",
      title);
  std::printf("%-28s | %6s %5s %8s %8s | %10s %9s | %7s %6s\n", "frame", "points", "hyps",
              "hit-rank", "mirr-rank", "nearest-m", "its-deg", "median", "cover");
  int hits = 0, mirror_hits = 0;
  for (const GlobalCheckFrame& f : frames) {
    hits += f.hit_rank >= 0;
    mirror_hits += f.mirror_hit_rank >= 0;
    std::printf("%-28s | %6d %5d %8d %8d | %10.2f %9.1f | %7.3f %6.3f\n", stem(f.image).c_str(),
                f.points, f.hypotheses, f.hit_rank, f.mirror_hit_rank, f.nearest_m,
                f.nearest_heading_rad * 180.0 / M_PI, f.metrics.median_distance_m,
                f.metrics.coverage);
  }
  std::printf("hits: %d of %d at the truth, %d at the mirrored truth\n", hits,
              static_cast<int>(frames.size()), mirror_hits);
}

}  // namespace houghloc
