#include "tools/offline/run_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace houghloc {
namespace {

double mean(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

void printTimeRow(const char* name, const std::vector<double>& values) {
  std::printf("  %-22s %9.3f %9.3f %9.3f\n", name, mean(values), quantile(values, 0.95),
              values.empty() ? 0.0 : *std::max_element(values.begin(), values.end()));
}

}  // namespace

double quantile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  const size_t rank =
      static_cast<size_t>(std::clamp(std::ceil(p * static_cast<double>(values.size())) - 1.0, 0.0,
                                     static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<long>(rank), values.end());
  return values[rank];
}

void printRunSummary(const std::string& title, const RunStats& s, int threads) {
  const int frames = s.processed + s.skipped;
  std::printf("%s\n", title.c_str());
  std::printf(
      "  frames %d: processed %d, skipped %d (missing/unreadable images, prediction only)\n",
      frames, s.processed, s.skipped);
  if (s.processed > 0) {
    std::printf("  points/frame %.1f   global localizer ran on %d frames\n",
                static_cast<double>(s.points) / s.processed, s.global_runs);
  }
  std::printf("  %-22s %9s %9s %9s\n", "time per frame [ms]", "mean", "p95", "max");
  printTimeRow("image loading", s.load_ms);
  printTimeRow("vision", s.vision_ms);
  printTimeRow("localization", s.localization_ms);
  printTimeRow("  of which global", s.global_ms);
  printTimeRow("sum", s.total_ms);
  if (s.wall_s > 0.0) {
    std::printf("  wall time %.2f s, %.1f frames/s (%d thread%s)\n", s.wall_s, frames / s.wall_s,
                threads, threads == 1 ? "" : "s");
  }
  std::printf("  status:");
  for (const char* name : {"INITIALIZING", "TRACKING", "AMBIGUOUS", "LOST"}) {
    const auto it = s.status_counts.find(name);
    const int count = it == s.status_counts.end() ? 0 : it->second;
    std::printf(" %s %d (%.0f%%)", name, count, frames > 0 ? 100.0 * count / frames : 0.0);
  }
  std::printf("\n");
  s.corrections.print();
}

}  // namespace houghloc
