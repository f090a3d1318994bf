// The end of step 4 in GlobalHoughLocalizer: duplicates merged, at most max_hypotheses selected
// (aware of the point-symmetric twins of a map), weights normalised.
#include <algorithm>
#include <limits>

#include "localization/gaussian_pose.h"
#include "localization/global_locate_state.h"

namespace houghloc {

HypothesisSetConfig GlobalHoughLocalizer::uncapped() const {
  HypothesisSetConfig all = config_.hypotheses;
  all.max_hypotheses = std::numeric_limits<int>::max();
  return all;
}

void GlobalHoughLocalizer::mergeRefined(LocateState& s) const {
  const HypothesisSetConfig all = uncapped();
  std::vector<PoseHypothesis> full, parallel;
  for (const PoseHypothesis& h : s.refined) {
    (h.kind == HypothesisKind::kParallel ? parallel : full).push_back(h);
  }
  s.merged = mergeDuplicates(std::move(full), all);
  for (PoseHypothesis& h : mergeDuplicates(std::move(parallel), all)) {
    s.merged.push_back(std::move(h));
  }
}

std::vector<PoseHypothesis> GlobalHoughLocalizer::selectHypotheses(LocateState& s) const {
  std::vector<PoseHypothesis>& merged = s.merged;
  std::stable_sort(merged.begin(), merged.end(),
                   [](const auto& a, const auto& b) { return a.score > b.score; });
  const HypothesisSetConfig& config = config_.hypotheses;
  const std::size_t max = static_cast<std::size_t>(std::max(0, config.max_hypotheses));
  std::vector<PoseHypothesis> out;
  if (merged.size() <= max || !map_.pointSymmetric()) {
    out.assign(merged.begin(), merged.begin() + std::min(max, merged.size()));
    normalizeWeights(out, config);
    return out;
  }
  std::vector<char> taken(merged.size(), 0);
  std::vector<std::size_t> chosen;
  for (std::size_t i = 0; i < merged.size() && chosen.size() < max; ++i) {
    PoseHypothesis twin = merged[i];
    twin.field_T_robot = mirrored(twin.field_T_robot);
    bool represented = false;
    for (std::size_t k : chosen) {
      // A full pose is not represented by a 1-D hypothesis on its line (it says where).
      represented |= merged[k].kind == twin.kind && sameHypothesis(merged[k], twin, config);
    }
    if (represented) continue;
    taken[i] = 1;
    chosen.push_back(i);
  }
  for (std::size_t i = 0; i < merged.size() && chosen.size() < max; ++i) {
    if (!taken[i]) chosen.push_back(i);
  }
  std::sort(chosen.begin(), chosen.end());  // the result stays sorted by score
  for (std::size_t i : chosen) out.push_back(std::move(merged[i]));
  normalizeWeights(out, config);
  return out;
}

}  // namespace houghloc
