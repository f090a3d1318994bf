// Step 4 of GlobalHoughLocalizer after pruning: refinement, observability, the paper's
// parallel-only Gaussian, and the final score with negative evidence.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "localization/gaussian_pose.h"
#include "localization/global_locate_state.h"

namespace houghloc {
namespace {

// The scan along lines visits every kCoarseStride-th position first; only next to the best of
// those and just outside their span where the points fit does it look at the positions between.
// A score changes along a line where the seen points pass a segment's end, over the kernel's
// width (0.15 m): a 0.3 m stride finds the truth on the same parallel-only frames as 0.2 m
// (docs/global-localization.md, "What keeps it fast").
constexpr std::size_t kCoarseStride = 3;

/// Interval of s for which t0 + s u stays inside |x| <= hx, |y| <= hy.
bool carpetInterval(const Eigen::Vector2d& t0, const Eigen::Vector2d& u, double hx, double hy,
                    double* s_min, double* s_max) {
  *s_min = -1e9;
  *s_max = 1e9;
  const double half[2] = {hx, hy};
  for (int k = 0; k < 2; ++k) {
    if (std::abs(u[k]) < 1e-9) {
      if (std::abs(t0[k]) > half[k]) return false;
      continue;
    }
    const double a = (-half[k] - t0[k]) / u[k], b = (half[k] - t0[k]) / u[k];
    *s_min = std::max(*s_min, std::min(a, b));
    *s_max = std::min(*s_max, std::max(a, b));
  }
  return *s_min <= *s_max;
}

}  // namespace

void GlobalHoughLocalizer::refineSurvivors(LocateState& s) const {
  double best = -1e300;  // the survivors come best first (converge)
  for (const PoseHypothesis& c : s.located) {
    for (PoseHypothesis& h :
         refineCandidate(c, s.fine, s.evidence, &s.line_scans, competingScore(best))) {
      best = std::max(best, h.score);
      s.refined.push_back(h);
      if (s.folded) s.refined.push_back(mirrored(h));
    }
  }
}

double GlobalHoughLocalizer::competingScore(double best) const {
  return best > 0.0 ? config_.pruning.min_relative_score * best : -1e300;
}

std::vector<PoseHypothesis> GlobalHoughLocalizer::refineCandidate(
    const PoseHypothesis& candidate, const WeightedPoints& points,
    const VisibilityEvidence& evidence, LineScans* scans, double min_score) const {
  PoseHypothesis h = candidate;
  const bool was_parallel = h.kind == HypothesisKind::kParallel;
  const Eigen::Vector2d frozen = was_parallel ? h.line_direction : Eigen::Vector2d::Zero();
  // A few iterations on the refinement points (the coarse ones on the pre-score subsample ran
  // in convergeCandidates).
  RefinementConfig fine = config_.refinement;
  fine.iterations = 3;
  RefinementResult r = refinePose(points, h.field_T_robot, map_, fine, frozen);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(r.information.topLeftCorner<2, 2>());
  const bool observed = eig.eigenvalues()(0) >= config_.min_observed_weight;
  if (observed && was_parallel) {
    r = refinePose(points, r.field_T_robot, map_, config_.refinement);
  }
  h.field_T_robot = r.field_T_robot;
  h.covariance = r.covariance;
  h.rms_m = r.rms_m;
  if (!observed) {
    // Only parallel lines constrain the position: the paper's case M = 1. The scan runs along
    // the whole line, so a survivor on a line scanned before (survivors converge to many places
    // on one line) would find the same hypothesis again.
    h.kind = HypothesisKind::kParallel;
    h.line_direction = eig.eigenvectors().col(0).normalized();
    if (lineScanned(scans->lines, h, false)) return {};
    std::vector<PoseHypothesis> placed;
    const int twin = scannedTwin(scans->lines, h);
    if (twin >= 0) {  // the twin scores the same (a point-symmetric map)
      for (const PoseHypothesis& t : scans->placed[twin]) {
        if (t.score >= min_score) placed.push_back(mirrored(t));
      }
    } else {
      if (scans->count >= config_.max_line_scans) return {};
      ++scans->count;
      placed = placeAlongLines(h, points, evidence, min_score);
    }
    scans->lines.push_back(h);
    scans->placed.push_back(placed);
    return placed;
  }
  h.kind = HypothesisKind::kFull;
  h.line_direction.setZero();
  finish(h, points, evidence);
  return {h};
}

std::vector<PoseHypothesis> GlobalHoughLocalizer::placeAlongLines(
    const PoseHypothesis& candidate, const WeightedPoints& points,
    const VisibilityEvidence& evidence, double min_score) const {
  const Eigen::Vector2d u = candidate.line_direction;
  const Eigen::Vector2d t0 = candidate.field_T_robot.translation();
  const double theta = candidate.field_T_robot.theta;
  double s_min, s_max;
  if (!carpetInterval(t0, u, map_.field().outerHalfLength(), map_.field().outerHalfWidth(), &s_min,
                      &s_max)) {
    return {};
  }
  // Scan along the lines: where the points fit the segments and no line is missing.
  const double step = config_.line_scan_step_m;
  const AlongLineScan scan =
      scanAlongLine(candidate, subsamplePoints(points, config_.prescore_points), evidence, s_min,
                    s_max, min_score);
  if (!scan.fit.found) return {};
  const AlongLineFit& fit = scan.fit;
  const std::vector<double>& s_values = scan.s_values;
  const double begin = s_values[fit.first], end = s_values[fit.last];
  // One Gaussian per line (the paper's M = 1 case): centred on the span of all stretches where
  // the points fit, with a standard deviation along the lines covering that whole span.
  const Eigen::Vector2d t = t0 + 0.5 * (begin + end) * u;
  PoseHypothesis h = candidate;
  const RefinementResult r =
      refinePose(points, Pose2(t.x(), t.y(), theta), map_, config_.refinement, u);
  h.field_T_robot = r.field_T_robot;
  const double along = 0.25 * (end - begin + 2.0 * step) + 0.3;
  const Eigen::Matrix2d p = Eigen::Matrix2d::Identity() - u * u.transpose();
  h.covariance = r.covariance;
  h.covariance.topLeftCorner<2, 2>() =
      p * r.covariance.topLeftCorner<2, 2>() * p + along * along * u * u.transpose();
  h.covariance.topRightCorner<2, 1>() = p * r.covariance.topRightCorner<2, 1>();
  h.covariance.bottomLeftCorner<1, 2>() = h.covariance.topRightCorner<2, 1>().transpose();
  h.covariance.topLeftCorner<2, 2>() += config_.parallel_floor_m * config_.parallel_floor_m * p;
  h.covariance(2, 2) += config_.parallel_floor_rad * config_.parallel_floor_rad;
  h.rms_m = r.rms_m;
  finish(h, points, evidence);
  // The score is that of the best position (the mean may sit between stretches).
  h.score = std::max(h.score, fit.best);
  return {h};
}

GlobalHoughLocalizer::AlongLineScan GlobalHoughLocalizer::scanAlongLine(
    const PoseHypothesis& candidate, const WeightedPoints& few, const VisibilityEvidence& evidence,
    double s_min, double s_max, double min_score) const {
  const Eigen::Vector2d u = candidate.line_direction;
  const Eigen::Vector2d t0 = candidate.field_T_robot.translation();
  const double theta = candidate.field_T_robot.theta;
  std::vector<double> fine;
  for (double s = s_min; s <= s_max + 1e-9; s += config_.line_scan_step_m) fine.push_back(s);
  AlongLineScan scan;
  if (fine.empty()) return scan;
  // Coarse to fine: the fit of every kCoarseStride-th position (and the last), then the fit of
  // those together with the positions between them next to the coarse best and just outside the
  // coarse span. A position's score does not depend on which others are scanned.
  const std::size_t n = fine.size();
  std::vector<char> visit(n, 0);
  for (std::size_t j = 0; j < n; j += kCoarseStride) visit[j] = 1;
  visit[n - 1] = 1;
  std::vector<std::size_t> coarse_index;
  std::vector<double> coarse_s;
  for (std::size_t j = 0; j < n; ++j) {
    if (!visit[j]) continue;
    coarse_index.push_back(j);
    coarse_s.push_back(fine[j]);
  }
  // A positive score bounds the score: empty when no position can reach min_score (the scan
  // stops early).
  const std::vector<double> coarse_scores =
      scoreAlongLine(few, theta, t0, u, coarse_s, map_.grid(), config_.scoring, min_score);
  if (coarse_scores.empty() ||
      *std::max_element(coarse_scores.begin(), coarse_scores.end()) < min_score) {
    return scan;
  }
  std::vector<double> coarse_upper = coarse_scores;
  std::vector<char> coarse_exact(coarse_s.size(), 0);
  const AlongLineFit coarse = fitAlongLine(candidate, coarse_s, coarse_scores, evidence,
                                           &coarse_upper, &coarse_exact, min_score);
  if (!coarse.found) return scan;
  auto visitBetween = [&](std::size_t from, std::size_t to) {  // fine indices, exclusive
    for (std::size_t j = from + 1; j < to; ++j) visit[j] = 2;
  };
  const std::size_t b = coarse.best_index, f = coarse.first, l = coarse.last;
  if (b > 0) visitBetween(coarse_index[b - 1], coarse_index[b]);
  if (b + 1 < coarse_index.size()) visitBetween(coarse_index[b], coarse_index[b + 1]);
  if (f > 0) visitBetween(coarse_index[f - 1], coarse_index[f]);
  if (l + 1 < coarse_index.size()) visitBetween(coarse_index[l], coarse_index[l + 1]);
  std::vector<double> extra_s;
  for (std::size_t j = 0; j < n; ++j) {
    if (visit[j] == 2) extra_s.push_back(fine[j]);
  }
  const std::vector<double> extra_scores =
      scoreAlongLine(few, theta, t0, u, extra_s, map_.grid(), config_.scoring);
  // What the coarse fit learnt of its positions' scores holds in the second fit too.
  std::vector<double> scores, upper;
  std::vector<char> exact;
  for (std::size_t j = 0, c = 0, e = 0; j < n; ++j) {
    if (visit[j] == 0) continue;
    scan.s_values.push_back(fine[j]);
    if (visit[j] == 1) {
      scores.push_back(coarse_scores[c]);
      upper.push_back(coarse_upper[c]);
      exact.push_back(coarse_exact[c++]);
    } else {
      scores.push_back(extra_scores[e]);
      upper.push_back(extra_scores[e++]);
      exact.push_back(0);
    }
  }
  scan.fit = fitAlongLine(candidate, scan.s_values, scores, evidence, &upper, &exact, min_score);
  return scan;
}

GlobalHoughLocalizer::AlongLineFit GlobalHoughLocalizer::fitAlongLine(
    const PoseHypothesis& candidate, const std::vector<double>& s_values,
    const std::vector<double>& positive, const VisibilityEvidence& evidence,
    std::vector<double>* upper_bounds, std::vector<char>* exact_scores, double min_score) const {
  // A position's score is its positive score less the negative evidence. Only three numbers of
  // all positions matter: the best score, and the first and the last position within the
  // tolerance of it (the span where the points fit). The penalty is >= 0, so a positive score
  // bounds a position's score from above, and so does it less the cheap part of the penalty
  // (field edge, then green beyond the carpet); the costly unseen-line term is paid only where
  // these bounds cannot decide.
  const Eigen::Vector2d u = candidate.line_direction;
  const Eigen::Vector2d t0 = candidate.field_T_robot.translation();
  const double theta = candidate.field_T_robot.theta;
  const std::size_t n = positive.size();
  std::vector<double>& upper = *upper_bounds;  // an upper bound of each score, or the score
  std::vector<char>& exact = *exact_scores;    // ... itself where exact
  // Raises upper[i] no more: the score when it can reach `level`, else a bound below `level`.
  auto scoreIfAbove = [&](std::size_t i, double level) {
    if (exact[i] || upper[i] < level) return;
    const Eigen::Vector2d t = t0 + s_values[i] * u;
    const Pose2 pose(t.x(), t.y(), theta);
    const double edge = evidence.edgePenalty(pose, map_.field());
    if (positive[i] - edge < level) {
      upper[i] = positive[i] - edge;
      return;
    }
    const VisibilityEvidence::CheapTerms cheap = evidence.cheapTerms(pose, map_.field(), edge);
    if (positive[i] - cheap.bound < level) {
      upper[i] = positive[i] - cheap.bound;
      return;
    }
    upper[i] = positive[i] - evidence.penalty(pose, map_, cheap);
    exact[i] = 1;
  };
  AlongLineFit fit;
  if (n == 0) return fit;
  // The best score, best positive score first: no position whose positive score is below the
  // best so far (or below min_score) can beat it.
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return positive[a] > positive[b]; });
  fit.best = -1e300;
  for (std::size_t i : order) {
    const double level = std::max(fit.best, min_score);
    if (level > -1e300 && positive[i] < level) break;
    scoreIfAbove(i, level);
    if (exact[i] && upper[i] > fit.best && upper[i] >= min_score) {
      fit.best = upper[i];
      fit.best_index = i;
    }
  }
  if (fit.best < min_score) return fit;
  // The first and the last position that reach the floor, each searched from its end.
  const double floor = fit.best - config_.line_scan_tolerance * std::max(std::abs(fit.best), 1.0);
  auto reaches = [&](std::size_t i) {
    scoreIfAbove(i, floor);
    return exact[i] && upper[i] >= floor;
  };
  std::size_t first = 0, last = n - 1;
  while (first < n && !reaches(first)) ++first;
  if (first == n) return fit;
  while (last > first && !reaches(last)) --last;
  fit.found = true;
  fit.first = first;
  fit.last = last;
  return fit;
}

void GlobalHoughLocalizer::finish(PoseHypothesis& h, const WeightedPoints& points,
                                  const VisibilityEvidence& evidence) const {
  const PoseScore s = scorePose(points, h.field_T_robot, map_.grid(), config_.scoring);
  h.penalty = evidence.penalty(h.field_T_robot, map_);
  h.score = s.score - h.penalty;
  h.inlier_share = s.inlier_share;
}

}  // namespace houghloc
