// Step 4 of GlobalHoughLocalizer after pruning: refinement, observability, the paper's
// parallel-only Gaussian, and the final score with negative evidence.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "localization/gaussian_pose.h"
#include "localization/global_locate_state.h"

namespace houghloc {
namespace {

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
  for (const PoseHypothesis& c : s.located) {
    for (PoseHypothesis& h : refineCandidate(c, s.fine, s.evidence, &s.line_scans)) {
      s.refined.push_back(std::move(h));
    }
  }
}

std::vector<PoseHypothesis> GlobalHoughLocalizer::refineCandidate(
    const PoseHypothesis& candidate, const WeightedPoints& points,
    const VisibilityEvidence& evidence, int* line_scans) const {
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
  if (!observed && *line_scans >= config_.max_line_scans) return {};
  h.field_T_robot = r.field_T_robot;
  h.covariance = r.covariance;
  h.rms_m = r.rms_m;
  if (!observed) {
    // Only parallel lines constrain the position: the paper's case M = 1.
    h.kind = HypothesisKind::kParallel;
    h.line_direction = eig.eigenvectors().col(0).normalized();
    ++*line_scans;
    return placeAlongLines(h, points, evidence);
  }
  h.kind = HypothesisKind::kFull;
  h.line_direction.setZero();
  finish(h, points, evidence);
  return {h};
}

std::vector<PoseHypothesis> GlobalHoughLocalizer::placeAlongLines(
    const PoseHypothesis& candidate, const WeightedPoints& points,
    const VisibilityEvidence& evidence) const {
  const Eigen::Vector2d u = candidate.line_direction;
  const Eigen::Vector2d t0 = candidate.field_T_robot.translation();
  const double theta = candidate.field_T_robot.theta;
  double s_min, s_max;
  if (!carpetInterval(t0, u, map_.field().outerHalfLength(), map_.field().outerHalfWidth(), &s_min,
                      &s_max)) {
    return {};
  }
  // Scan along the lines: where the points fit the segments and no line is missing.
  const WeightedPoints few = subsamplePoints(points, config_.prescore_points);
  const double step = config_.line_scan_step_m;
  std::vector<double> s_values;
  for (double s = s_min; s <= s_max + 1e-9; s += step) s_values.push_back(s);
  std::vector<double> scores =
      scoreAlongLine(few, theta, t0, u, s_values, map_.grid(), config_.scoring);
  if (scores.empty()) return {};
  // Subtract the negative evidence lazily, best positive score first: the penalty is >= 0, so
  // once a position's positive score is below the floor of the best total so far, neither it
  // nor any later one can reach the floor.
  std::vector<std::size_t> order(scores.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return scores[a] > scores[b]; });
  const double tolerance = config_.line_scan_tolerance;
  auto floorOf = [&](double b) { return b - tolerance * std::max(std::abs(b), 1.0); };
  double best = -1e300;
  std::vector<char> done(scores.size(), 0);
  for (std::size_t i : order) {
    if (best > -1e300 && scores[i] < floorOf(best)) break;
    const Eigen::Vector2d t = t0 + s_values[i] * u;
    const Pose2 pose(t.x(), t.y(), theta);
    // A position that stays below the floor even with the cheap part of its penalty cannot raise
    // `best` nor reach the final floor (the floor only rises): skip the costly unseen-line term.
    // The field edge alone (a part of that bound, cheaper than the green beyond the carpet)
    // decides most of them.
    const double edge = evidence.edgePenalty(pose, map_.field());
    if (best > -1e300 && scores[i] - edge < floorOf(best)) continue;
    const VisibilityEvidence::CheapTerms cheap = evidence.cheapTerms(pose, map_.field(), edge);
    if (best > -1e300 && scores[i] - cheap.bound < floorOf(best)) continue;
    scores[i] -= evidence.penalty(pose, map_, cheap);
    done[i] = 1;
    best = std::max(best, scores[i]);
  }
  for (std::size_t i = 0; i < scores.size(); ++i) {
    if (!done[i]) scores[i] = -1e300;  // below the floor
  }
  const double floor = floorOf(best);
  struct Stretch {
    double begin, end, top;
  };
  std::vector<Stretch> stretches;
  for (std::size_t i = 0; i < scores.size(); ++i) {
    if (scores[i] < floor) continue;
    if (i > 0 && scores[i - 1] >= floor) {
      stretches.back().end = s_values[i];
      stretches.back().top = std::max(stretches.back().top, scores[i]);
    } else {
      stretches.push_back({s_values[i], s_values[i], scores[i]});
    }
  }
  if (stretches.empty()) return {};
  // One Gaussian per line (the paper's M = 1 case): centred on the span of all stretches where
  // the points fit, with a standard deviation along the lines covering that whole span.
  const double begin = stretches.front().begin, end = stretches.back().end;
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
  // The score is that of the best stretch (the mean may sit between stretches).
  h.score = std::max(h.score, stretches.front().top);
  for (const Stretch& st : stretches) h.score = std::max(h.score, st.top);
  return {h};
}

void GlobalHoughLocalizer::finish(PoseHypothesis& h, const WeightedPoints& points,
                                  const VisibilityEvidence& evidence) const {
  const PoseScore s = scorePose(points, h.field_T_robot, map_.grid(), config_.scoring);
  h.penalty = evidence.penalty(h.field_T_robot, map_);
  h.score = s.score - h.penalty;
  h.inlier_share = s.inlier_share;
}

}  // namespace houghloc
