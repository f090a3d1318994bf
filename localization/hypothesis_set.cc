#include "localization/hypothesis_set.h"

#include <algorithm>
#include <cmath>

namespace houghloc {

bool sameHypothesis(const PoseHypothesis& a, const PoseHypothesis& b,
                    const HypothesisSetConfig& config) {
  if (std::abs(angleDifference(a.field_T_robot.theta, b.field_T_robot.theta)) >
      config.merge_angle_rad) {
    return false;
  }
  const Eigen::Vector2d d = a.field_T_robot.translation() - b.field_T_robot.translation();
  if (a.kind == HypothesisKind::kHeadingOnly || b.kind == HypothesisKind::kHeadingOnly) {
    return a.kind == b.kind;
  }
  // Two 1-D hypotheses on the same line are one. A full pose on a 1-D hypothesis' line is not
  // its duplicate: it says where along the line, which the wide 1-D Gaussian does not.
  if (a.kind == HypothesisKind::kParallel && b.kind == HypothesisKind::kParallel) {
    const PoseHypothesis* line = &a;
    // Same line, and along it within the larger of the two along-line std devs.
    const Eigen::Vector2d& u = line->line_direction;
    const double along_sigma = std::sqrt(std::max(u.dot(a.covariance.topLeftCorner<2, 2>() * u),
                                                  u.dot(b.covariance.topLeftCorner<2, 2>() * u)));
    return std::abs(d.x() * u.y() - d.y() * u.x()) <= config.merge_distance_m &&
           std::abs(d.dot(u)) <= std::max(along_sigma, config.merge_distance_m);
  }
  return d.norm() <= config.merge_distance_m;
}

std::vector<PoseHypothesis> mergeDuplicates(std::vector<PoseHypothesis> hypotheses,
                                            const HypothesisSetConfig& config) {
  std::stable_sort(
      hypotheses.begin(), hypotheses.end(),
      [](const PoseHypothesis& a, const PoseHypothesis& b) { return a.score > b.score; });
  std::vector<PoseHypothesis> out;
  for (const auto& h : hypotheses) {
    if (static_cast<int>(out.size()) >= config.max_hypotheses) break;
    bool duplicate = false;
    for (const auto& kept : out) duplicate |= sameHypothesis(kept, h, config);
    if (!duplicate) out.push_back(h);
  }
  return out;
}

void normalizeWeights(std::vector<PoseHypothesis>& hypotheses, const HypothesisSetConfig& config) {
  if (hypotheses.empty()) return;
  double best = -1e300;
  for (const auto& h : hypotheses) best = std::max(best, h.score);
  const double scale = std::max(1e-9, config.temperature * std::max(std::abs(best), 1.0));
  double sum = 0.0;
  for (auto& h : hypotheses) {
    h.weight = std::exp((h.score - best) / scale);
    sum += h.weight;
  }
  for (auto& h : hypotheses) h.weight /= sum;
}

}  // namespace houghloc
