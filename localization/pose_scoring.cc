#include "localization/pose_scoring.h"

#include <algorithm>
#include <cmath>

#include "localization/hypothesis_set.h"

namespace houghloc {

namespace {

/// Beyond both the kernel width and the inlier distance a point adds exactly nothing, so the grid
/// is only read near lines (distanceBelow; the 1e-9 keeps d == width out of the question).
/// scoreAlongLine must use the same limit to give scorePose's numbers.
double contributionLimit(const ScoringConfig& config) {
  return std::max(config.kernel_width_m, config.inlier_distance_m) + 1e-9;
}

/// The robust kernel k(d) = max(0, 1 - (d / width)^2), with inv_w2 = 1 / width^2.
double kernel(double d, double inv_w2) { return std::max(0.0, 1.0 - d * d * inv_w2); }

/// Sum over the points at field positions position(i), in batches: first the positions and a
/// prefetch of the grid nodes near lines, then the lookups, so that the cache misses of a batch
/// overlap instead of following one another.
template <typename Position>
PoseScore scoreAt(const std::vector<double>& weights, Position&& position, const DistanceGrid& grid,
                  const ScoringConfig& config) {
  PoseScore out;
  const double inv_w2 = 1.0 / (config.kernel_width_m * config.kernel_width_m);
  const double limit = contributionLimit(config);
  double total = 0.0, inliers = 0.0;
  constexpr std::size_t kBatch = 32;
  Eigen::Vector2d q[kBatch];
  const std::size_t size = weights.size();
  for (std::size_t start = 0; start < size; start += kBatch) {
    const std::size_t n = std::min(kBatch, size - start);
    for (std::size_t k = 0; k < n; ++k) {
      q[k] = position(start + k);
      grid.prefetch(q[k], limit);
    }
    for (std::size_t k = 0; k < n; ++k) {
      const double d = grid.distanceBelow(q[k], limit);
      const double w = weights[start + k];
      total += w;
      out.score += w * kernel(d, inv_w2);
      if (d <= config.inlier_distance_m) inliers += w;
    }
  }
  out.inlier_share = total > 0.0 ? inliers / total : 0.0;
  return out;
}

}  // namespace

PoseScore scorePose(const WeightedPoints& points, const Pose2& pose, const DistanceGrid& grid,
                    const ScoringConfig& config) {
  if (points.empty() || !pose.isFinite()) return {};
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  return scoreAt(
      points.weights,
      [&](std::size_t i) {
        const Eigen::Vector2d& p = points.points[i];
        return Eigen::Vector2d(c * p.x() - s * p.y() + pose.x, s * p.x() + c * p.y() + pose.y);
      },
      grid, config);
}

std::vector<PoseScore> scoreTranslations(const WeightedPoints& points, double theta_rad,
                                         const std::vector<Eigen::Vector2d>& translations,
                                         const DistanceGrid& grid, const ScoringConfig& config) {
  std::vector<PoseScore> out(translations.size());
  const double theta = Pose2(0.0, 0.0, theta_rad).theta;  // normalised, as scorePose sees it
  if (points.empty() || !std::isfinite(theta)) return out;
  // c x - s y + t_x is evaluated left to right, so rotating first gives the same bits.
  const double c = std::cos(theta), s = std::sin(theta);
  std::vector<double> rx(points.size()), ry(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d& p = points.points[i];
    rx[i] = c * p.x() - s * p.y();
    ry[i] = s * p.x() + c * p.y();
  }
  for (std::size_t k = 0; k < translations.size(); ++k) {
    const double tx = translations[k].x(), ty = translations[k].y();
    if (!std::isfinite(tx) || !std::isfinite(ty)) continue;
    out[k] = scoreAt(
        points.weights, [&](std::size_t i) { return Eigen::Vector2d(rx[i] + tx, ry[i] + ty); },
        grid, config);
  }
  return out;
}

std::vector<double> scoreAlongLine(const WeightedPoints& points, double theta_rad,
                                   const Eigen::Vector2d& t0, const Eigen::Vector2d& u,
                                   const std::vector<double>& s_values, const DistanceGrid& grid,
                                   const ScoringConfig& config, double reach) {
  const std::size_t n = s_values.size();
  std::vector<double> out(n, 0.0);
  std::vector<double> tx(n), ty(n);
  bool finite = std::isfinite(Pose2(0.0, 0.0, theta_rad).theta);
  for (std::size_t j = 0; j < n; ++j) {
    const Eigen::Vector2d t = t0 + s_values[j] * u;  // as the caller builds its poses
    tx[j] = t.x();
    ty[j] = t.y();
    finite = finite && std::isfinite(tx[j]) && std::isfinite(ty[j]);
  }
  if (points.empty()) return out;
  if (!finite) {  // the plain way; scorePose scores a non-finite pose 0
    for (std::size_t j = 0; j < n; ++j) {
      out[j] = scorePose(points, Pose2(tx[j], ty[j], theta_rad), grid, config).score;
    }
    return out;
  }
  const double theta = Pose2(0.0, 0.0, theta_rad).theta;
  const double c = std::cos(theta), s = std::sin(theta);
  const double inv_w2 = 1.0 / (config.kernel_width_m * config.kernel_width_m);
  const double limit = contributionLimit(config);
  // Moves along the scan are measured in s; |u| and the rounding of t0 + s u add at most this.
  const double u_norm = u.norm() * (1.0 + 1e-12);
  const double u_l1 = (std::abs(u.x()) + std::abs(u.y())) * (1.0 + 1e-12);
  constexpr double kRoundingM = 1e-9;
  // The early stop: the weight of the points still to come, and the best sum so far. The margin
  // covers the rounding of the sums, so a scan stops only where every score stays below reach.
  const bool may_stop = reach > -std::numeric_limits<double>::infinity();
  double to_come = points.totalWeight(), best = 0.0;
  const double margin = 1e-9 * (std::abs(to_come) + std::abs(reach));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d& p = points.points[i];
    const double rx = c * p.x() - s * p.y(), ry = s * p.x() + c * p.y();
    const double w = points.weights[i];
    bool near = false;
    for (std::size_t j = 0; j < n;) {
      const Eigen::Vector2d q(rx + tx[j], ry + ty[j]);  // scorePose's c x - s y + t_x
      // After a position near a line the next is usually near one too (the scan runs along the
      // seen lines): interpolate at once. Below the limit both lookups return the same value,
      // above it both make the kernel exactly zero.
      const double d = near ? grid.distance(q) : grid.distanceBelow(q, limit);
      near = d < limit;
      out[j] += w * kernel(d, inv_w2);
      best = std::max(best, out[j]);
      std::size_t next = j + 1;
      if (d > limit) {  // the point adds exactly zero up to `far` further on
        const double far = grid.farMove(grid.onGrid(q), d, limit, u_l1, u_norm, kRoundingM);
        while (next < n && s_values[next] - s_values[j] <= far) ++next;
      }
      j = next;
    }
    to_come -= w;
    if (may_stop && best + to_come + margin < reach) return {};
  }
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
