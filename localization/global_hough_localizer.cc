#include "localization/global_hough_localizer.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "localization/gaussian_pose.h"
#include "localization/global_locate_state.h"

namespace houghloc {

GlobalHoughLocalizer::GlobalHoughLocalizer(const FieldModel& field, const GlobalHoughConfig& config)
    : config_(config), map_(field, config.map) {}

std::vector<PoseHypothesis> GlobalHoughLocalizer::locate(const GroundPoints& frame) const {
  const WeightedPoints points = preparePoints(frame);
  if (!hasLineSupport(points)) return {};
  // Negative evidence (beyond the paper): the seen region and the field edge, which count
  // against hypotheses that predict lines where none are seen or put the view off the carpet.
  VisibilityEvidence evidence(frame, points, config_.negative);
  LocateState s(points, evidence, config_);
  const HoughTransform sensor = sensorTransform(points);  // step 1: HT_S
  s.headings = orientationCandidates(sensor);             // step 2: headings theta_R
  if (s.headings.empty()) return {};
  foldTwins(s);  // point-symmetric map: one heading of each twin pair, the twins mirrored back
  for (const OrientationCandidate& heading : s.headings) {  // steps 3 and 4: constraints, poses
    addPoseCandidates(heading.theta_rad, translationConstraints(points, heading.theta_rad), s);
  }
  addLandmarkPoses(s);  // landmarks: the centre circle or a penalty mark fixes a pose alone
  gateFieldEdge(s);     // field edge: an edge that no candidate explains is not the carpet's
  if (s.located.empty()) return headingOnly(s);  // step 4, M = 0: no translation fits
  scoreAndPrune(s);    // step 4: score against the whole map, prune by segment extents
  converge(s);         // coarse Gauss-Newton: one candidate per optimum
  refineSurvivors(s);  // step 4: refine, final score with negative evidence, 1-D if parallel
  mergeRefined(s);     // step 4: merge duplicates, full poses and 1-D hypotheses apart
  addEveryLine(s);     // parallel lines: every map line of the seen direction, if only those
  return selectHypotheses(s);  // symmetry-aware selection: each twin pair once, then weights
}

WeightedPoints GlobalHoughLocalizer::preparePoints(const GroundPoints& frame) const {
  WeightedPoints all;
  for (const GroundPoint& g : frame.points) {
    if (!g.p_robot.allFinite() || !(g.weight > 0.0) || !std::isfinite(g.weight)) continue;
    if (g.p_robot.norm() > config_.max_range_m) continue;
    all.points.push_back(g.p_robot);
    all.weights.push_back(g.weight);
  }
  return subsamplePoints(all, config_.max_points);
}

bool GlobalHoughLocalizer::hasLineSupport(const WeightedPoints& points) const {
  if (points.size() < config_.min_points) return false;
  const double total = points.totalWeight();
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) mean += points.weights[i] * points.points[i];
  mean /= total;
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d d = points.points[i] - mean;
    cov += points.weights[i] * d * d.transpose();
  }
  cov /= total;
  const double spread = std::sqrt(std::max(0.0, cov.eigenvalues().real().maxCoeff()));
  return std::isfinite(spread) && spread >= config_.min_spread_m;
}

HoughTransform GlobalHoughLocalizer::sensorTransform(const WeightedPoints& points) const {
  double range = config_.map.hough.rho_step_m;
  for (const auto& p : points.points) range = std::max(range, p.norm());
  HoughTransform transform(config_.map.hough, range);
  transform.addPoints(points);
  return transform;
}

std::vector<OrientationCandidate> GlobalHoughLocalizer::orientationCandidates(
    const HoughTransform& sensor) const {
  return findOrientationCandidates(orientationProfile(sensor), map_.profile(), config_.orientation);
}

std::vector<std::vector<TranslationConstraint>> GlobalHoughLocalizer::translationConstraints(
    const WeightedPoints& points, double theta_r) const {
  std::vector<std::vector<TranslationConstraint>> out;
  for (int k = 0; k < static_cast<int>(map_.dominantDirections().size()); ++k) {
    out.push_back(findTranslationConstraints(points, map_, k, theta_r, config_.translation));
  }
  return out;
}

void GlobalHoughLocalizer::addPoseCandidates(
    double theta_r, const std::vector<std::vector<TranslationConstraint>>& constraints,
    LocateState& s) const {
  for (PoseHypothesis& h : lineCandidates(theta_r, constraints, config_.solver)) {
    s.lines.push_back(std::move(h));
  }
  // Candidates number in the hundreds and are large structs: moved, never copied.
  for (PoseHypothesis& h : solvePoses(theta_r, constraints, config_.solver)) {
    if (h.kind == HypothesisKind::kHeadingOnly) {
      s.heading_only.push_back(std::move(h));
    } else if (onCarpet(h.field_T_robot)) {
      s.located.push_back(std::move(h));
    }
  }
}

void GlobalHoughLocalizer::gateFieldEdge(LocateState& s) const {
  if (s.evidence.edgeEmpty()) return;
  std::vector<Pose2> poses;
  poses.reserve(s.located.size());
  for (const PoseHypothesis& h : s.located) poses.push_back(h.field_T_robot);
  s.evidence.keepEdgeIfAnyFits(poses, map_.field());
}

void GlobalHoughLocalizer::foldTwins(LocateState& s) const {
  if (!map_.pointSymmetric()) return;
  s.folded = true;
  std::vector<OrientationCandidate> kept;
  for (const OrientationCandidate& h : s.headings) {
    bool twin_kept = false;
    for (const OrientationCandidate& k : kept) {
      twin_kept |= std::abs(angleDifference(k.theta_rad + M_PI, h.theta_rad)) < 1e-9;
    }
    if (!twin_kept) kept.push_back(h);
  }
  s.headings.swap(kept);
}

std::vector<PoseHypothesis> GlobalHoughLocalizer::headingOnly(LocateState& s) const {
  if (s.folded) {
    const std::size_t n = s.heading_only.size();
    for (std::size_t i = 0; i < n; ++i) s.heading_only.push_back(mirrored(s.heading_only[i]));
  }
  for (PoseHypothesis& h : s.heading_only) h.score = h.support;
  std::vector<PoseHypothesis> out = mergeDuplicates(s.heading_only, config_.hypotheses);
  normalizeWeights(out, config_.hypotheses);
  return out;
}

bool GlobalHoughLocalizer::onCarpet(const Pose2& pose) const {
  return pose.isFinite() && std::abs(pose.x) <= map_.field().outerHalfLength() &&
         std::abs(pose.y) <= map_.field().outerHalfWidth();
}

}  // namespace houghloc
