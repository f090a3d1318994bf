// Beyond the paper: poses from the centre circle and the penalty marks, each of which fixes a
// pose on its own with a heading (a lone arc of the circle fits every rotation about its centre:
// the rotations are scanned, ranked with the field edge when it is seen).
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "localization/global_locate_state.h"

namespace houghloc {
namespace {

// Points scored per heading of the scan about a landmark.
constexpr std::size_t kScanPoints = 30;
// The fine rotation search about a landmark, in tenths of the coarse step: from the coarse
// maximum, the better of the two neighbours at each stride in turn. 6, 3 and 1 reach every tenth
// within one coarse step on either side (|6 + 3 + 1| = 10) with 6 scores instead of 20.
constexpr int kFineSteps = 10;
constexpr int kFineStrides[] = {6, 3, 1};

}  // namespace

void GlobalHoughLocalizer::addLandmarkPoses(LocateState& s) const {
  for (PoseHypothesis& h : landmarkPoses(s.points, s.headings, &s.evidence, s.folded)) {
    if (!onCarpet(h.field_T_robot)) continue;
    (h.kind == HypothesisKind::kHeadingOnly ? s.heading_only : s.located).push_back(std::move(h));
  }
}

std::vector<PoseHypothesis> GlobalHoughLocalizer::landmarkPoses(
    const WeightedPoints& points, const std::vector<OrientationCandidate>& headings,
    const VisibilityEvidence* evidence, bool folded) const {
  std::vector<PoseHypothesis> out;
  const WeightedPoints few = subsamplePoints(points, kScanPoints);
  auto append = [&](const Eigen::Vector2d& p_robot, const Eigen::Vector2d& p_field,
                    HypothesisSource source, double support) {
    // A rotation about the field's centre and the one half a turn on are twins.
    const bool half_turn = folded && p_field.norm() < 1e-9;
    std::vector<OrientationCandidate> all = headings;
    for (const auto& h : scanHeadings(p_robot, p_field, few, evidence, half_turn)) {
      all.push_back(h);
    }
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
    const VisibilityEvidence* evidence, bool half_turn) const {
  // Rotations about the landmark: p_field = R(theta) p_robot + t keeps the landmark in place.
  auto scoreAt = [&](double theta) {
    const Eigen::Vector2d t = p_field - Eigen::Rotation2Dd(theta) * p_robot;
    const Pose2 pose(t.x(), t.y(), theta);
    return scorePose(points, pose, map_.grid(), config_.scoring).score -
           (evidence ? evidence->edgePenalty(pose, map_.field()) : 0.0);
  };
  const int per_turn = std::max(
      8, static_cast<int>(std::lround(2.0 * M_PI / config_.landmarks.heading_scan_step_rad)));
  const int n = half_turn && per_turn % 2 == 0 ? per_turn / 2 : per_turn;  // scores kept, cyclic
  std::vector<double> score(n);
  for (int k = 0; k < n; ++k) score[k] = scoreAt(2.0 * M_PI * k / per_turn);
  std::vector<OrientationCandidate> maxima;
  for (int k = 0; k < n; ++k) {
    const double prev = score[(k + n - 1) % n], next = score[(k + 1) % n];
    if (score[k] > prev && score[k] >= next) {
      maxima.push_back({normalizeAngle(2.0 * M_PI * k / per_turn), score[k]});
    }
  }
  std::sort(maxima.begin(), maxima.end(),
            [](const auto& a, const auto& b) { return a.correlation > b.correlation; });
  // Over half a turn each maximum stands for itself and its twin.
  const int kept = half_turn && n < per_turn ? (config_.landmarks.heading_scan_maxima + 1) / 2
                                             : config_.landmarks.heading_scan_maxima;
  if (static_cast<int>(maxima.size()) > kept) maxima.resize(kept);
  // A lone arc leaves the rotation to the field edge, whose cost varies smoothly: place each
  // maximum between its neighbours at a tenth of the step (far from the landmark a 2 deg step
  // moves the robot by more than the 0.1 m a pose may be off), searched with kFineStrides.
  if (evidence && !evidence->edgeEmpty()) {
    const double step = 2.0 * M_PI / per_turn;
    for (OrientationCandidate& m : maxima) {
      const double centre = m.theta_rad;
      int best = 0;  // in tenths of the step from the centre
      for (int stride : kFineStrides) {
        const int from = best;
        for (int k : {from - stride, from + stride}) {
          const double theta = centre + step * k / kFineSteps;
          const double s = scoreAt(theta);
          if (s > m.correlation) {
            m = {normalizeAngle(theta), s};
            best = k;
          }
        }
      }
    }
  }
  return maxima;
}

}  // namespace houghloc
