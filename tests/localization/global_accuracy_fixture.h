#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "field_models/pose2.h"
#include "localization/pose_hypothesis.h"
#include "tools/offline/evaluation_frames.h"  // median, correctRankUpToSymmetry

namespace houghloc {

/// Results of GlobalHoughLocalizer (and optionally the grid search) on synthetic frames with two
/// directions in view (DESIGN §5.3), from random poses.
struct AccuracySummary {
  int frames = 0;
  /// Correct up to symmetry (DESIGN §5.3, 0.10 m / 3 deg): at any rank, as the best, among the
  /// two best distinct answers (tools/offline CorrectRank: a twin shares its pair's rank).
  int ghl_any = 0, ghl_top1 = 0, ghl_top2 = 0;
  int grid_any = 0, grid_top1 = 0;
  int ghl_positive_any = 0;               ///< GHL without negative evidence
  std::vector<double> position_errors_m;  ///< of the correct GHL hypothesis
  std::vector<double> heading_errors_rad;
  double ghl_seconds = 0.0, grid_seconds = 0.0;  ///< CPU time

  double rate(int count) const { return frames > 0 ? 100.0 * count / frames : 0.0; }
  std::string describe(const std::string& label) const;
};

struct AccuracyRun {
  std::string field = "spl";
  std::string view = "nao-top";
  int frames = 20;
  std::uint64_t seed = 1;
  bool grid = false;           ///< also run the exhaustive reference
  bool positive_only = false;  ///< also run GHL without negative evidence
};

AccuracySummary evaluateGlobal(const AccuracyRun& run);

/// Parallel-only frames: how often the truth (or its mirror) is within 3 sigma (Mahalanobis
/// over x, y, theta) of a kParallel hypothesis.
struct ParallelSummary {
  int frames = 0;
  int within = 0;
};
ParallelSummary evaluateParallelOnly(const AccuracyRun& run);

}  // namespace houghloc
