#include "localization/global_hough_localizer.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "localization/gaussian_pose.h"

namespace houghloc {
namespace {

// Candidates whose coarse refinement ends this close are the same optimum.
constexpr double kConvergedM = 0.03;
constexpr double kConvergedRad = 0.01;
// Candidates kept after the cheap first scoring round, in multiples of PruningConfig::keep.
constexpr int kFirstRoundShare = 4;
// Points scored per heading of the scan about a landmark.
constexpr std::size_t kScanPoints = 30;
// Gauss-Newton iterations of the coarse stage (on the pre-score subsample).
constexpr int kCoarseIterations = 6;
// Steps per side of the fine rotation scan about a landmark, in tenths of the coarse step.
constexpr int kFineScanSteps = 10;

/// At most config.max_hypotheses of the merged, sorted hypotheses. On a point-symmetric map a
/// pose and its twin (-x, -y, theta + pi) explain every frame equally well, so when there are
/// more distinct hypotheses than slots, each pair is first represented once (best first) and
/// twins fill the slots that are left; the result stays sorted by score.
std::vector<PoseHypothesis> selectHypotheses(const std::vector<PoseHypothesis>& merged,
                                             bool symmetric, const HypothesisSetConfig& config) {
  const std::size_t max = static_cast<std::size_t>(std::max(0, config.max_hypotheses));
  if (merged.size() <= max || !symmetric) {
    return {merged.begin(), merged.begin() + std::min(max, merged.size())};
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
  std::sort(chosen.begin(), chosen.end());
  std::vector<PoseHypothesis> out;
  for (std::size_t i : chosen) out.push_back(merged[i]);
  return out;
}

}  // namespace

GlobalHoughLocalizer::GlobalHoughLocalizer(const FieldModel& field, const GlobalHoughConfig& config)
    : config_(config), map_(field, config.map) {}

std::vector<PoseHypothesis> GlobalHoughLocalizer::locate(const GroundPoints& frame) const {
  const WeightedPoints points = preparePoints(frame);
  if (!hasLineSupport(points)) return {};
  VisibilityEvidence evidence(frame, points, config_.negative);
  const HoughTransform sensor = sensorTransform(points);                             // step 1
  const std::vector<OrientationCandidate> headings = orientationCandidates(sensor);  // step 2
  if (headings.empty()) return {};
  std::vector<PoseHypothesis> candidates, lines;
  for (const OrientationCandidate& heading : headings) {
    const auto constraints = translationConstraints(points, heading.theta_rad);  // step 3
    for (PoseHypothesis& h : lineCandidates(heading.theta_rad, constraints, config_.solver)) {
      lines.push_back(h);
    }
    for (PoseHypothesis& h : solvePoses(heading.theta_rad, constraints, config_.solver)) {  // 4
      if (h.kind == HypothesisKind::kHeadingOnly || onCarpet(h.field_T_robot)) {
        candidates.push_back(h);
      }
    }
  }
  for (PoseHypothesis& h : landmarkPoses(points, headings, &evidence)) {  // beyond the paper
    if (onCarpet(h.field_T_robot)) candidates.push_back(h);
  }
  // An edge that no candidate explains is not the carpet's (see max_best_cost): ignore it from
  // here on, so it cannot shift every score by the same penalty.
  if (!evidence.edgeEmpty()) {
    std::vector<Pose2> poses;
    poses.reserve(candidates.size());
    for (const PoseHypothesis& h : candidates) {
      if (h.kind != HypothesisKind::kHeadingOnly) poses.push_back(h.field_T_robot);
    }
    evidence.keepEdgeIfAnyFits(poses, map_.field());
  }
  // Candidates number in the hundreds and are large structs: move, and free them at once (on
  // SPL a fifth of locate() went to page faults from growing and trimming these vectors).
  std::vector<PoseHypothesis> located, heading_only;
  located.reserve(candidates.size());
  for (PoseHypothesis& h : candidates) {
    (h.kind == HypothesisKind::kHeadingOnly ? heading_only : located).push_back(std::move(h));
  }
  candidates = {};
  if (located.empty()) {  // the paper's case M = 0: lines seen, no translation fits
    for (PoseHypothesis& h : heading_only) h.score = h.support;
    auto out = mergeDuplicates(heading_only, config_.hypotheses);
    normalizeWeights(out, config_.hypotheses);
    return out;
  }
  // Step 4 scoring, in two rounds: a quarter of the pre-score points ranks all candidates, the
  // best few times `keep` are scored with all pre-score points, then pruned by segment extents.
  const WeightedPoints few = subsamplePoints(points, config_.prescore_points);
  if (located.size() > static_cast<std::size_t>(kFirstRoundShare * config_.pruning.keep)) {
    scoreCandidates(located, subsamplePoints(points, config_.prescore_points / 4), &evidence);
    // Sort indices, not the structs; same order as a stable sort of the candidates.
    std::vector<std::size_t> order(located.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return located[a].score > located[b].score;
    });
    const std::size_t kept = static_cast<std::size_t>(kFirstRoundShare * config_.pruning.keep);
    std::vector<PoseHypothesis> best;
    best.reserve(kept);
    for (std::size_t k = 0; k < kept; ++k) best.push_back(std::move(located[order[k]]));
    located.swap(best);
  }
  scoreCandidates(located, few, &evidence);
  located = pruneCandidates(located, config_.pruning);
  located = convergeCandidates(located, few, evidence);
  std::vector<PoseHypothesis> refined;
  int line_scans = 0;
  const WeightedPoints fine = subsamplePoints(points, config_.refine_points);
  for (const PoseHypothesis& c : located) {
    for (PoseHypothesis& h : refineCandidate(c, fine, evidence, &line_scans)) {
      refined.push_back(h);
    }
  }
  HypothesisSetConfig all = config_.hypotheses;
  all.max_hypotheses = std::numeric_limits<int>::max();
  // Full poses and 1-D hypotheses are merged separately: a full pose near a 1-D hypothesis' mean
  // is not its duplicate (it says where along the line, which the 1-D one does not).
  std::vector<PoseHypothesis> full, parallel;
  for (PoseHypothesis& h : refined) {
    (h.kind == HypothesisKind::kParallel ? parallel : full).push_back(h);
  }
  std::vector<PoseHypothesis> merged = mergeDuplicates(full, all);
  for (PoseHypothesis& h : mergeDuplicates(parallel, all)) merged.push_back(h);
  if (parallelOnlyFrame(refined, fine)) {
    // The 1-D candidates that survived pruning are a few of the field's lines; try them all.
    // A new 1-D hypothesis replaces a weaker one on the same line; a full pose near its mean
    // stays (it says where along the line).
    for (PoseHypothesis& h : mergeDuplicates(everyLineHypotheses(lines, fine, evidence), all)) {
      bool known = false;
      for (PoseHypothesis& m : merged) {
        if (known || m.kind != HypothesisKind::kParallel || !sameHypothesis(m, h, all)) continue;
        known = true;
        if (h.score > m.score) m = h;
      }
      if (!known) merged.push_back(h);
    }
  }
  std::stable_sort(merged.begin(), merged.end(),
                   [](const auto& a, const auto& b) { return a.score > b.score; });
  std::vector<PoseHypothesis> out =
      selectHypotheses(merged, map_.pointSymmetric(), config_.hypotheses);
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
    const WeightedPoints& points, const std::vector<OrientationCandidate>& headings,
    const VisibilityEvidence* evidence) const {
  std::vector<PoseHypothesis> out;
  const WeightedPoints few = subsamplePoints(points, kScanPoints);
  auto append = [&](const Eigen::Vector2d& p_robot, const Eigen::Vector2d& p_field,
                    HypothesisSource source, double support) {
    std::vector<OrientationCandidate> all = headings;
    for (const auto& h : scanHeadings(p_robot, p_field, few, evidence)) all.push_back(h);
    for (auto& h : landmarkCandidates(p_robot, p_field, all, source, support)) out.push_back(h);
  };
  if (config_.use_circle) {
    for (const Arc2& circle : map_.circles()) {
      const auto seen = fitCircle(points, circle.radius, config_.landmarks);
      if (seen) append(seen->center, circle.center, HypothesisSource::kCircle, seen->support);
    }
  }
  if (config_.use_marks && !map_.field().marks.empty()) {
    // Marks are small and blobs can be clutter: the step-2 headings only (no scan).
    const double size = map_.field().marks.back().size;
    for (const Eigen::Vector2d& blob : findMarkBlobs(points, size, config_.landmarks)) {
      for (const Mark& mark : map_.field().marks) {
        for (auto& h :
             landmarkCandidates(blob, mark.center, headings, HypothesisSource::kMark, 1.0)) {
          out.push_back(h);
        }
      }
    }
  }
  return out;
}

std::vector<OrientationCandidate> GlobalHoughLocalizer::scanHeadings(
    const Eigen::Vector2d& p_robot, const Eigen::Vector2d& p_field, const WeightedPoints& points,
    const VisibilityEvidence* evidence) const {
  // Rotations about the landmark: p_field = R(theta) p_robot + t keeps the landmark in place.
  auto scoreAt = [&](double theta) {
    const Eigen::Vector2d t = p_field - Eigen::Rotation2Dd(theta) * p_robot;
    const Pose2 pose(t.x(), t.y(), theta);
    return scorePose(points, pose, map_.grid(), config_.scoring).score -
           (evidence ? evidence->edgePenalty(pose, map_.field()) : 0.0);
  };
  const int n = std::max(
      8, static_cast<int>(std::lround(2.0 * M_PI / config_.landmarks.heading_scan_step_rad)));
  std::vector<double> score(n);
  for (int k = 0; k < n; ++k) score[k] = scoreAt(2.0 * M_PI * k / n);
  std::vector<OrientationCandidate> maxima;
  for (int k = 0; k < n; ++k) {
    const double prev = score[(k + n - 1) % n], next = score[(k + 1) % n];
    if (score[k] > prev && score[k] >= next) {
      maxima.push_back({normalizeAngle(2.0 * M_PI * k / n), score[k]});
    }
  }
  std::sort(maxima.begin(), maxima.end(),
            [](const auto& a, const auto& b) { return a.correlation > b.correlation; });
  if (static_cast<int>(maxima.size()) > config_.landmarks.heading_scan_maxima) {
    maxima.resize(config_.landmarks.heading_scan_maxima);
  }
  // A lone arc leaves the rotation to the field edge, whose cost varies smoothly: place each
  // maximum between its neighbours at a tenth of the step (far from the landmark a 2 deg step
  // moves the robot by more than the 0.1 m a pose may be off).
  if (evidence && !evidence->edgeEmpty()) {
    const double step = 2.0 * M_PI / n;
    for (OrientationCandidate& m : maxima) {
      const double centre = m.theta_rad;
      for (int k = -kFineScanSteps; k <= kFineScanSteps; ++k) {
        const double theta = centre + step * k / kFineScanSteps;
        const double s = k == 0 ? m.correlation : scoreAt(theta);
        if (s > m.correlation) m = {normalizeAngle(theta), s};
      }
    }
  }
  return maxima;
}

std::vector<PoseHypothesis> GlobalHoughLocalizer::convergeCandidates(
    std::vector<PoseHypothesis> candidates, const WeightedPoints& few,
    const VisibilityEvidence& evidence) const {
  // Gauss-Newton on the subsample first: candidates from different Hough peaks often converge
  // to the same optimum, and only distinct optima need the full refinement.
  RefinementConfig coarse = config_.refinement;
  coarse.max_distance_m *= 1.5;
  coarse.iterations = std::min(coarse.iterations, kCoarseIterations);
  coarse.converged_m = 1e-3;  // the fine stage follows
  for (PoseHypothesis& c : candidates) {
    const Eigen::Vector2d frozen =
        c.kind == HypothesisKind::kParallel ? c.line_direction : Eigen::Vector2d::Zero();
    c.field_T_robot = refinePoseMean(few, c.field_T_robot, map_, coarse, frozen);
    c.score = scorePose(few, c.field_T_robot, map_.grid(), config_.scoring).score -
              evidence.edgePenalty(c.field_T_robot, map_.field());
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.score > b.score; });
  std::vector<PoseHypothesis> out;
  for (const PoseHypothesis& c : candidates) {
    bool same = false;
    for (const PoseHypothesis& k : out) {
      same |=
          k.kind == c.kind &&
          (k.field_T_robot.translation() - c.field_T_robot.translation()).norm() < kConvergedM &&
          std::abs(angleDifference(k.field_T_robot.theta, c.field_T_robot.theta)) < kConvergedRad;
    }
    if (!same) out.push_back(c);
  }
  return out;
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
