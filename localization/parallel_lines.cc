// Beyond the paper's step 4 for frames with only parallel lines in view: the paper's M = 1
// Gaussian leaves open which map line was seen, so every map line of the seen direction is tried,
// each placed along its line by the scan of placeAlongLines().
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "localization/gaussian_pose.h"
#include "localization/global_locate_state.h"

namespace houghloc {
namespace {

// 1-D candidates closer than this in heading and across the lines are the same line.
constexpr double kSameLineRad = 0.03;
constexpr double kSameLineM = 0.06;
// A frame whose best full pose has less than this many times min_observed_weight across its
// weakest direction counts as parallel-only when a 1-D hypothesis scores about as well (a few
// outliers or a line's end make a pose observable).
constexpr double kParallelOnlyObserved = 3.0;

}  // namespace

void GlobalHoughLocalizer::addEveryLine(LocateState& s) const {
  if (!parallelOnlyFrame(s.refined, s.fine)) return;
  // The 1-D candidates that survived pruning are a few of the field's lines; try them all.
  // A new 1-D hypothesis replaces a weaker one on the same line; a full pose near its mean
  // stays (it says where along the line).
  const HypothesisSetConfig all = uncapped();
  double best = -1e300;
  for (const PoseHypothesis& m : s.merged) best = std::max(best, m.score);
  for (PoseHypothesis& h : mergeDuplicates(
           everyLineHypotheses(s.lines, s.line_scans.lines, s.fine, s.evidence, best), all)) {
    bool known = false;
    for (PoseHypothesis& m : s.merged) {
      if (known || m.kind != HypothesisKind::kParallel || !sameHypothesis(m, h, all)) continue;
      known = true;
      if (h.score > m.score) m = h;
    }
    if (!known) s.merged.push_back(h);
  }
}

bool GlobalHoughLocalizer::lineScanned(const std::vector<PoseHypothesis>& scanned,
                                       const PoseHypothesis& line, bool mirrors) const {
  const Pose2& p = line.field_T_robot;
  return scannedLineIndex(scanned, p) >= 0 ||
         (mirrors && scannedLineIndex(scanned, mirrored(p)) >= 0);
}

int GlobalHoughLocalizer::scannedTwin(const std::vector<PoseHypothesis>& scanned,
                                      const PoseHypothesis& line) const {
  return map_.pointSymmetric() ? scannedLineIndex(scanned, mirrored(line.field_T_robot)) : -1;
}

int GlobalHoughLocalizer::scannedLineIndex(const std::vector<PoseHypothesis>& scanned,
                                           const Pose2& pose) {
  for (std::size_t i = 0; i < scanned.size(); ++i) {
    if (onScannedLine(scanned[i], pose)) return static_cast<int>(i);
  }
  return -1;
}

bool GlobalHoughLocalizer::onScannedLine(const PoseHypothesis& scanned, const Pose2& pose) {
  const Eigen::Vector2d d = pose.translation() - scanned.field_T_robot.translation();
  const Eigen::Vector2d& u = scanned.line_direction;
  return std::abs(angleDifference(scanned.field_T_robot.theta, pose.theta)) < kSameLineRad &&
         std::abs(d.x() * u.y() - d.y() * u.x()) < kSameLineM;
}

bool GlobalHoughLocalizer::parallelOnlyFrame(const std::vector<PoseHypothesis>& refined,
                                             const WeightedPoints& points) const {
  const PoseHypothesis* best_full = nullptr;
  double best_parallel = -1e300;
  for (const PoseHypothesis& h : refined) {
    if (h.kind == HypothesisKind::kParallel) best_parallel = std::max(best_parallel, h.score);
    if (h.kind == HypothesisKind::kFull && (best_full == nullptr || h.score > best_full->score)) {
      best_full = &h;
    }
  }
  if (best_parallel == -1e300) return false;
  if (best_full == nullptr) return true;
  if (best_parallel < config_.parallel_only_share * best_full->score) return false;
  // A full pose about as good as the best 1-D one, or a little worse: free along its lines, a
  // 1-D hypothesis at the same place fits the same points a fraction of a point better. A second
  // direction is in view only if clearly more than the few points that made the full pose
  // observable lie across the lines.
  RefinementConfig none = config_.refinement;
  none.iterations = 0;
  const RefinementResult r = refinePose(points, best_full->field_T_robot, map_, none);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(r.information.topLeftCorner<2, 2>());
  return eig.eigenvalues()(0) < kParallelOnlyObserved * config_.min_observed_weight;
}

std::vector<PoseHypothesis> GlobalHoughLocalizer::everyLineHypotheses(
    const std::vector<PoseHypothesis>& lines, const std::vector<PoseHypothesis>& placed,
    const WeightedPoints& points, const VisibilityEvidence& evidence, double best_score) const {
  const bool symmetric = map_.pointSymmetric();
  const double min_score = competingScore(best_score);
  std::vector<PoseHypothesis> scanned, out;
  for (const PoseHypothesis& line : lines) {
    if (lineScanned(placed, line, symmetric) || lineScanned(scanned, line, symmetric)) continue;
    scanned.push_back(line);
    for (const PoseHypothesis& h : placeAlongLines(line, points, evidence, min_score)) {
      out.push_back(h);
      if (!symmetric) continue;
      out.push_back(mirrored(h));  // the map is point-symmetric: the twin scores the same
    }
  }
  return out;
}

}  // namespace houghloc
