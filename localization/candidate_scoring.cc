// Step 4 of GlobalHoughLocalizer before the refinement: every candidate scored against the whole
// map, pruned by segment extents, and one kept per optimum of a coarse Gauss-Newton.
#include <algorithm>
#include <cmath>
#include <functional>

#include "localization/gaussian_pose.h"
#include "localization/global_locate_state.h"

namespace houghloc {
namespace {

// Candidates whose coarse refinement ends this close are the same optimum.
constexpr double kConvergedM = 0.03;
constexpr double kConvergedRad = 0.01;
// Candidates kept after the cheap first scoring round, in multiples of PruningConfig::keep.
constexpr int kFirstRoundShare = 4;
// Gauss-Newton iterations of the coarse stage (on the pre-score subsample).
constexpr int kCoarseIterations = 6;

/// Whether two candidates' coarse refinements ended at the same optimum.
bool sameOptimum(const PoseHypothesis& a, const PoseHypothesis& b) {
  return a.kind == b.kind &&
         (a.field_T_robot.translation() - b.field_T_robot.translation()).norm() < kConvergedM &&
         std::abs(angleDifference(a.field_T_robot.theta, b.field_T_robot.theta)) < kConvergedRad;
}

}  // namespace

void GlobalHoughLocalizer::scoreAndPrune(LocateState& s) const {
  std::vector<PoseHypothesis>& located = s.located;
  // Folded, each candidate stands for two: half as many keep the same number of poses.
  PruningConfig pruning = config_.pruning;
  if (s.folded) pruning.keep = (pruning.keep + 1) / 2;
  const std::size_t kept = static_cast<std::size_t>(kFirstRoundShare * pruning.keep);
  if (located.size() > kept) keepBestOfFirstRound(located, kept, s);
  scoreCandidates(located, s.few, &s.evidence);
  located = pruneCandidates(std::move(located), pruning);
}

void GlobalHoughLocalizer::keepBestOfFirstRound(std::vector<PoseHypothesis>& located,
                                                std::size_t kept, LocateState& s) const {
  // The cheap round: the positive score on a few points for every candidate, the field-edge
  // penalty only for those that can still be among the `kept` best. The penalty is >= 0 (as
  // placeAlongLines assumes), so once a candidate's positive score is below the kept-th best
  // total so far, neither it nor any weaker one can enter; the candidates kept, their order and
  // their scores are those of scoring all (round two rescores them anyway).
  scoreCandidates(located, subsamplePoints(s.points, config_.prescore_points / 4), nullptr);
  auto byScore = [&](std::size_t a, std::size_t b) { return located[a].score > located[b].score; };
  std::vector<std::size_t> order(located.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), byScore);
  std::vector<std::size_t> scored;
  std::vector<double> best_totals;  // min-heap of the kept best totals so far
  for (std::size_t i : order) {
    PoseHypothesis& c = located[i];
    if (best_totals.size() == kept && c.score < best_totals.front()) break;
    c.score -= s.evidence.edgePenalty(c.field_T_robot, map_.field());
    scored.push_back(i);
    best_totals.push_back(c.score);
    std::push_heap(best_totals.begin(), best_totals.end(), std::greater<double>());
    if (best_totals.size() > kept) {
      std::pop_heap(best_totals.begin(), best_totals.end(), std::greater<double>());
      best_totals.pop_back();
    }
  }
  // Same order as a stable sort of all candidates by total score: ties keep the input order.
  std::sort(scored.begin(), scored.end());
  std::stable_sort(scored.begin(), scored.end(), byScore);
  std::vector<PoseHypothesis> best;
  best.reserve(kept);
  for (std::size_t k = 0; k < kept; ++k) best.push_back(std::move(located[scored[k]]));
  located.swap(best);
}

void GlobalHoughLocalizer::converge(LocateState& s) const {
  // Gauss-Newton on the subsample first: candidates from different Hough peaks often converge
  // to the same optimum, and only distinct optima need the full refinement.
  RefinementConfig coarse = config_.refinement;
  coarse.max_distance_m *= 1.5;
  coarse.iterations = std::min(coarse.iterations, kCoarseIterations);
  coarse.converged_m = 1e-3;  // the fine stage follows
  std::vector<PoseHypothesis>& candidates = s.located;
  for (PoseHypothesis& c : candidates) {
    const Eigen::Vector2d frozen =
        c.kind == HypothesisKind::kParallel ? c.line_direction : Eigen::Vector2d::Zero();
    c.field_T_robot = refinePoseMean(s.few, c.field_T_robot, map_, coarse, frozen);
    c.score = scorePose(s.few, c.field_T_robot, map_.grid(), config_.scoring).score -
              s.evidence.edgePenalty(c.field_T_robot, map_.field());
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.score > b.score; });
  std::vector<PoseHypothesis> out;
  for (PoseHypothesis& c : candidates) {
    bool same = false;
    for (const PoseHypothesis& k : out) {
      same |= sameOptimum(k, c) || (s.folded && sameOptimum(mirrored(k), c));
    }
    if (!same) out.push_back(std::move(c));
  }
  candidates.swap(out);
}

void GlobalHoughLocalizer::scoreCandidates(std::vector<PoseHypothesis>& candidates,
                                           const WeightedPoints& points,
                                           const VisibilityEvidence* evidence) const {
  for (PoseHypothesis& c : candidates) {
    const PoseScore s = scorePose(points, c.field_T_robot, map_.grid(), config_.scoring);
    c.score = s.score - (evidence ? evidence->edgePenalty(c.field_T_robot, map_.field()) : 0.0);
    c.inlier_share = s.inlier_share;
  }
}

}  // namespace houghloc
