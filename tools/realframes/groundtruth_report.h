#pragma once

#include <vector>

#include "tools/realframes/groundtruth_frames.h"

namespace houghloc {

/// The share of the map's visible line samples covered by a point, pooled over frames: houghloc's
/// and the column-scan baseline's, of the same samples.
struct PooledCoverage {
  long visible = 0, covered = 0, baseline_covered = 0;
  double share() const { return visible > 0 ? static_cast<double>(covered) / visible : 0.0; }
  double baselineShare() const {
    return visible > 0 ? static_cast<double>(baseline_covered) / visible : 0.0;
  }
};
PooledCoverage pooledCoverage(const std::vector<GroundTruthFrameReport>& frames);

/// houghloc-real-report's section on the frames with a ground-truth pose: one row per frame,
/// houghloc beside the column-scan baseline.
void printGroundTruthFrames(const std::vector<GroundTruthFrameReport>& frames);

/// The --global-only check of one folder: one row per ground-truth frame and the hit counts.
void printGlobalCheck(const char* title, const std::vector<GlobalCheckFrame>& frames);

}  // namespace houghloc
