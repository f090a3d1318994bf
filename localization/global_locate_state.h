#pragma once
// Internal to GlobalHoughLocalizer: the state one locate() call hands from stage to stage.

#include <vector>

#include "localization/global_hough_localizer.h"

namespace houghloc {

struct GlobalHoughLocalizer::LocateState {
  LocateState(const WeightedPoints& all, VisibilityEvidence& negative,
              const GlobalHoughConfig& config)
      : points(all),
        evidence(negative),
        few(subsamplePoints(all, config.prescore_points)),
        fine(subsamplePoints(all, config.refine_points)) {}

  const WeightedPoints& points;  ///< the prepared points (step 1 and the landmark fits)
  VisibilityEvidence& evidence;  ///< negative evidence; gateFieldEdge() may drop its edge
  const WeightedPoints few;      ///< prescore_points subsample: second scoring round, converge()
  const WeightedPoints fine;     ///< refine_points subsample: refinement, scans along lines
  std::vector<OrientationCandidate> headings;  ///< step 2 (one of each twin pair when folded)
  /// A point-symmetric map: a pose and its twin (-x, -y, theta + pi) explain every frame alike,
  /// so steps 3 and 4 run on one heading of each pair (foldTwins()) and every candidate stands
  /// for itself and its twin, which refineSurvivors() adds as the mirror of its refinement.
  bool folded = false;
  /// Candidates with a position (full and 1-D, on the carpet), in the order found; after
  /// scoreAndPrune() and converge() the survivors.
  std::vector<PoseHypothesis> located;
  std::vector<PoseHypothesis> heading_only;  ///< step 4 without a translation (M = 0)
  std::vector<PoseHypothesis> lines;         ///< every 1-D line candidate of step 4
  std::vector<PoseHypothesis> refined;       ///< refineSurvivors() output, unmerged
  std::vector<PoseHypothesis> merged;        ///< distinct hypotheses, full and 1-D
  LineScans line_scans;                      ///< the survivors' scans along lines
};

}  // namespace houghloc
