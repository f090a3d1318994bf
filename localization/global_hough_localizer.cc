#include "localization/global_hough_localizer.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace houghloc {

GlobalHoughLocalizer::GlobalHoughLocalizer(const FieldModel& field, const GlobalHoughConfig& config)
    : config_(config), map_(field, config.map) {}

std::vector<PoseHypothesis> GlobalHoughLocalizer::locate(const GroundPoints& frame) const {
  const WeightedPoints points = preparePoints(frame);
  if (!hasLineSupport(points)) return {};
  const HoughTransform sensor = sensorTransform(points);                             // step 1
  const std::vector<OrientationCandidate> headings = orientationCandidates(sensor);  // step 2
  if (headings.empty()) return {};
  std::vector<PoseHypothesis> candidates;
  for (const OrientationCandidate& heading : headings) {
    const auto constraints = translationConstraints(points, heading.theta_rad);  // step 3
    for (PoseHypothesis& h : solvePoses(heading.theta_rad, constraints, config_.solver)) {  // 4
      if (h.kind == HypothesisKind::kHeadingOnly || onCarpet(h.field_T_robot)) {
        candidates.push_back(h);
      }
    }
  }
  for (PoseHypothesis& h : landmarkPoses(points, headings)) {  // beyond the paper
    if (onCarpet(h.field_T_robot)) candidates.push_back(h);
  }
  std::vector<PoseHypothesis> located, heading_only;
  for (PoseHypothesis& h : candidates) {
    (h.kind == HypothesisKind::kHeadingOnly ? heading_only : located).push_back(h);
  }
  if (located.empty()) {  // the paper's case M = 0: lines seen, no translation fits
    for (PoseHypothesis& h : heading_only) h.score = h.support;
    auto out = mergeDuplicates(heading_only, config_.hypotheses);
    normalizeWeights(out, config_.hypotheses);
    return out;
  }
  scoreCandidates(located, subsamplePoints(points, config_.prescore_points));  // step 4 ...
  located = pruneCandidates(located, config_.pruning);  // ... segment extents
  const VisibilityEvidence evidence(frame, points, config_.negative);
  std::vector<PoseHypothesis> refined;
  int line_scans = 0;
  for (const PoseHypothesis& c : located) {
    for (PoseHypothesis& h : refineCandidate(c, points, evidence, &line_scans)) {
      refined.push_back(h);
    }
  }
  std::vector<PoseHypothesis> out = mergeDuplicates(refined, config_.hypotheses);
  normalizeWeights(out, config_.hypotheses);
  return out;
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

std::vector<PoseHypothesis> GlobalHoughLocalizer::landmarkPoses(
    const WeightedPoints& points, const std::vector<OrientationCandidate>& headings) const {
  std::vector<PoseHypothesis> out;
  auto append = [&out](std::vector<PoseHypothesis> more) {
    out.insert(out.end(), more.begin(), more.end());
  };
  if (config_.use_circle) {
    for (const Arc2& circle : map_.circles()) {
      const auto seen = fitCircle(points, circle.radius, config_.landmarks);
      if (seen) {
        append(landmarkCandidates(seen->center, circle.center, headings, HypothesisSource::kCircle,
                                  seen->support));
      }
    }
  }
  if (config_.use_marks && !map_.field().marks.empty()) {
    const double size = map_.field().marks.back().size;
    for (const Eigen::Vector2d& blob : findMarkBlobs(points, size, config_.landmarks)) {
      for (const Mark& mark : map_.field().marks) {
        append(landmarkCandidates(blob, mark.center, headings, HypothesisSource::kMark, 1.0));
      }
    }
  }
  return out;
}

void GlobalHoughLocalizer::scoreCandidates(std::vector<PoseHypothesis>& candidates,
                                           const WeightedPoints& points) const {
  for (PoseHypothesis& c : candidates) {
    const PoseScore s = scorePose(points, c.field_T_robot, map_.grid(), config_.scoring);
    c.score = s.score;
    c.inlier_share = s.inlier_share;
  }
}

bool GlobalHoughLocalizer::onCarpet(const Pose2& pose) const {
  return pose.isFinite() && std::abs(pose.x) <= map_.field().outerHalfLength() &&
         std::abs(pose.y) <= map_.field().outerHalfWidth();
}

double GlobalHoughLocalizer::totalScore(const Pose2& pose, const WeightedPoints& points,
                                        const VisibilityEvidence& evidence, double* penalty) const {
  const double p = evidence.penalty(pose, map_);
  if (penalty != nullptr) *penalty = p;
  return scorePose(points, pose, map_.grid(), config_.scoring).score - p;
}

}  // namespace houghloc
