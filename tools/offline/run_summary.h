#pragma once

#include <map>
#include <string>
#include <vector>

#include "tools/offline/correction_summary.h"

namespace houghloc {

/// Per-frame figures of a localization run, collected for the summary table.
struct RunStats {
  int processed = 0;  ///< frames whose image went through vision
  int skipped = 0;    ///< frames whose image was missing or unreadable (prediction only)
  long points = 0;
  std::vector<double> load_ms, vision_ms, localization_ms, global_ms, total_ms;
  int global_runs = 0;  ///< frames on which the global localizer ran
  std::map<std::string, int> status_counts;
  double wall_s = 0.0;            ///< whole run, including output
  CorrectionSummary corrections;  ///< the pitch/roll corrector per camera
};

/// The summary table on stdout: frames processed/skipped, mean and p95 time per frame for image
/// loading, vision, localization (of which global) and the sum, frames per second, status counts,
/// the camera pitch/roll correction.
void printRunSummary(const std::string& title, const RunStats& stats, int threads);

/// p-quantile (0..1) of `values` by nearest rank; 0 for none.
double quantile(std::vector<double> values, double p);

}  // namespace houghloc
