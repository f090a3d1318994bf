#pragma once

#include <vector>

#include "localization/pose_hypothesis.h"
#include "tools/offline/offline_context.h"

namespace houghloc {

/// When the single-frame hypotheses of --global-only count as AMBIGUOUS.
struct GlobalStatusConfig {
  /// The runner-up's weight relative to the best one's from which the two compete.
  double comparable_weight_ratio = 0.5;
  /// Two hypotheses closer than this (m and rad) describe the same pose.
  double same_position_m = 0.5;
  double same_heading_rad = 0.35;
};

/// --global-only status of one frame's hypotheses (best first): LOST when there are none,
/// AMBIGUOUS when the best two have comparable weight and are not the same pose (a mirror
/// pair included), TRACKING otherwise.
const char* globalOnlyStatus(const std::vector<PoseHypothesis>& hypotheses,
                             const GlobalStatusConfig& config = {});

/// --global-only (DESIGN §5.2, issue 6): vision and GlobalHoughLocalizer::locate() on every frame
/// independently (no tracking, no odometry, no hints). Heading-only hypotheses (lines seen, no
/// position) are not written: their mean is no position. Writes poses.csv, hypotheses.csv,
/// timing.csv (points.csv with --points), the `global` section of metrics.json and
/// trajectory.png. Returns the exit code; throws for input and output errors.
int runGlobalOnly(const OfflineContext& context);

}  // namespace houghloc
