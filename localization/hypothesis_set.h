#pragma once

#include <vector>

#include "localization/pose_hypothesis.h"

namespace houghloc {

struct HypothesisSetConfig {
  double merge_distance_m = 0.25;  ///< hypotheses closer than this ...
  double merge_angle_rad = 0.1;    ///< ... and this in heading are duplicates
  double temperature = 0.05;       ///< weights ~ exp((score - best) / (temperature * best))
  int max_hypotheses = 12;         ///< at most this many are returned
};

/// True when a and b describe the same pose (for two kParallel ones: the same line, any position
/// along it).
bool sameHypothesis(const PoseHypothesis& a, const PoseHypothesis& b,
                    const HypothesisSetConfig& config);

/// Step 4 "merge duplicates": sorts by score, keeps the best of each group of duplicates, at most
/// max_hypotheses.
std::vector<PoseHypothesis> mergeDuplicates(std::vector<PoseHypothesis> hypotheses,
                                            const HypothesisSetConfig& config);

/// Step 4 "normalise weights": softmax of the scores relative to the best, summing to 1.
void normalizeWeights(std::vector<PoseHypothesis>& hypotheses, const HypothesisSetConfig& config);

}  // namespace houghloc
