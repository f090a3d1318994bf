#include "localization/pose_scoring.h"

#include <algorithm>
#include <cmath>

#include "localization/hypothesis_set.h"

namespace houghloc {

PoseScore scorePose(const WeightedPoints& points, const Pose2& pose, const DistanceGrid& grid,
                    const ScoringConfig& config) {
  PoseScore out;
  if (points.empty() || !pose.isFinite()) return out;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double inv_w2 = 1.0 / (config.kernel_width_m * config.kernel_width_m);
  double total = 0.0, inliers = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d& p = points.points[i];
    const Eigen::Vector2d q(c * p.x() - s * p.y() + pose.x, s * p.x() + c * p.y() + pose.y);
    const double d = grid.distance(q);
    const double w = points.weights[i];
    total += w;
    out.score += w * std::max(0.0, 1.0 - d * d * inv_w2);
    if (d <= config.inlier_distance_m) inliers += w;
  }
  out.inlier_share = total > 0.0 ? inliers / total : 0.0;
  return out;
}

std::vector<PoseHypothesis> pruneCandidates(std::vector<PoseHypothesis> candidates,
                                            const PruningConfig& config) {
  std::sort(candidates.begin(), candidates.end(),
            [](const PoseHypothesis& a, const PoseHypothesis& b) { return a.score > b.score; });
  if (candidates.empty()) return candidates;
  const double best = candidates.front().score;
  HypothesisSetConfig same;
  same.merge_distance_m = config.duplicate_distance_m;
  same.merge_angle_rad = config.duplicate_angle_rad;
  std::vector<PoseHypothesis> out;
  for (const auto& c : candidates) {
    if (static_cast<int>(out.size()) >= config.keep) break;
    if (c.inlier_share < config.min_inlier_share) continue;
    if (c.score < config.min_relative_score * best) continue;
    bool duplicate = false;
    for (const auto& kept : out) duplicate |= sameHypothesis(kept, c, same);
    if (!duplicate) out.push_back(c);
  }
  return out;
}

WeightedPoints subsamplePoints(const WeightedPoints& points, std::size_t max_points) {
  if (points.size() <= max_points || max_points == 0) return points;
  WeightedPoints out;
  const double stride = static_cast<double>(points.size()) / max_points;
  const double scale = stride;  // keeps the total weight, so scores stay comparable
  for (std::size_t k = 0; k < max_points; ++k) {
    const std::size_t i = static_cast<std::size_t>(k * stride);
    out.points.push_back(points.points[i]);
    out.weights.push_back(points.weights[i] * scale);
  }
  return out;
}

}  // namespace houghloc
