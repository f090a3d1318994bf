#include "localization/landmarks.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace houghloc {
namespace {

constexpr std::size_t kMaxVotingPoints = 100;  // points voting for the circle centre

/// Coverage of angles around a centre: 2 pi minus the largest gap between sorted angles.
double angularCoverage(std::vector<double> angles) {
  if (angles.size() < 2) return 0.0;
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2.0 * M_PI - angles.back();
  for (std::size_t i = 1; i < angles.size(); ++i) gap = std::max(gap, angles[i] - angles[i - 1]);
  return 2.0 * M_PI - gap;
}

}  // namespace

std::optional<CircleObservation> fitCircle(const WeightedPoints& points, double radius,
                                           const LandmarkConfig& config) {
  if (points.size() < 3 || !(radius > 0.0)) return std::nullopt;
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const auto& p : points.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double cell = config.circle_cell_m;
  lo -= Eigen::Vector2d::Constant(radius + cell);
  hi += Eigen::Vector2d::Constant(radius + cell);
  const int cols = static_cast<int>((hi.x() - lo.x()) / cell) + 1;
  const int rows = static_cast<int>((hi.y() - lo.y()) / cell) + 1;
  if (static_cast<double>(cols) * rows > 4e6) return std::nullopt;  // absurd extent
  std::vector<float> votes(static_cast<std::size_t>(cols) * rows, 0.0f);
  const int steps = std::max(16, static_cast<int>(std::ceil(2.0 * M_PI * radius / cell)));
  std::vector<Eigen::Vector2d> ring(steps);
  for (int k = 0; k < steps; ++k) {
    ring[k] = (radius / cell) *
              Eigen::Vector2d(std::cos(2 * M_PI * k / steps), std::sin(2 * M_PI * k / steps));
  }
  // The vote only needs to land in the right cell: an even subsample of the points is enough
  // (Gauss-Newton below uses all of them).
  const std::size_t stride = std::max<std::size_t>(1, points.size() / kMaxVotingPoints);
  // The best cell's count is kept in a register: comparing against votes[best] in memory would
  // chain every vote to the previous one through a store and a load.
  int best = -1;
  float best_votes = 0.0f;
  for (std::size_t i = 0; i < points.size(); i += stride) {
    const Eigen::Vector2d p = (points.points[i] - lo) / cell;
    const float w = static_cast<float>(points.weights[i]);
    for (const auto& r : ring) {
      const int idx = static_cast<int>(p.y() + r.y()) * cols + static_cast<int>(p.x() + r.x());
      const float v = votes[idx] += w;
      if (best < 0 || v > best_votes) {
        best = idx;
        best_votes = v;
      }
    }
  }
  Eigen::Vector2d centre = lo + cell * Eigen::Vector2d(best % cols + 0.5, best / cols + 0.5);
  // Gauss-Newton on r_i = |p_i - c| - radius over the points near the circle.
  double support = 0.0;
  std::vector<double> angles;
  for (int it = 0; it < 6; ++it) {
    Eigen::Matrix2d h = Eigen::Matrix2d::Zero();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    support = 0.0;
    angles.clear();
    const double band = it < 2 ? 2.0 * config.circle_band_m : config.circle_band_m;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector2d v = points.points[i] - centre;
      const double n = v.norm();
      if (n < 1e-9 || std::abs(n - radius) > band) continue;
      const Eigen::Vector2d j = -v / n;
      h += points.weights[i] * j * j.transpose();
      b += points.weights[i] * j * (n - radius);
      support += points.weights[i];
      if (it == 5) angles.push_back(std::atan2(v.y(), v.x()));  // coverage of the final fit
    }
    if (support <= 0.0 || h.determinant() < 1e-9) return std::nullopt;
    centre -= h.ldlt().solve(b);
  }
  CircleObservation out{centre, support, angularCoverage(angles)};
  const double tangent_arc = 2.0 * std::sqrt(2.0 * config.circle_band_m / radius);
  const double min_arc =
      std::max(config.circle_min_arc_rad, config.circle_tangent_factor * tangent_arc);
  if (out.support < config.circle_min_support || out.arc_rad < min_arc || !centre.allFinite()) {
    return std::nullopt;
  }
  return out;
}

std::vector<Eigen::Vector2d> findMarkBlobs(const WeightedPoints& points, double mark_size,
                                           const LandmarkConfig& config) {
  std::vector<Eigen::Vector2d> out;
  const double cell = config.mark_isolation_m;
  std::unordered_map<long long, std::vector<int>> grid;
  auto key = [&](const Eigen::Vector2d& p, int dc, int dr) {
    const long long c = static_cast<long long>(std::floor(p.x() / cell)) + dc;
    const long long r = static_cast<long long>(std::floor(p.y() / cell)) + dr;
    return c * 1000003LL + r;
  };
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
    grid[key(points.points[i], 0, 0)].push_back(i);
  const double blob_radius = 0.5 * mark_size + config.mark_link_m;
  std::vector<char> used(points.size(), 0);
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    if (used[i]) continue;
    const Eigen::Vector2d& p = points.points[i];
    std::vector<int> near;
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        auto it = grid.find(key(p, dc, dr));
        if (it == grid.end()) continue;
        for (int j : it->second) {
          if ((points.points[j] - p).norm() <= config.mark_isolation_m) near.push_back(j);
        }
      }
    }
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (int j : near) centre += points.points[j];
    centre /= static_cast<double>(near.size());
    bool compact = static_cast<int>(near.size()) >= config.mark_min_points;
    for (int j : near) compact &= (points.points[j] - centre).norm() <= blob_radius;
    for (int j : near) used[j] = 1;
    if (compact) out.push_back(centre);
    if (static_cast<int>(out.size()) >= config.max_marks) break;
  }
  return out;
}

std::vector<PoseHypothesis> landmarkCandidates(const Eigen::Vector2d& p_robot,
                                               const Eigen::Vector2d& p_field,
                                               const std::vector<OrientationCandidate>& headings,
                                               HypothesisSource source, double support) {
  std::vector<PoseHypothesis> out;
  for (const auto& h : headings) {
    const double c = std::cos(h.theta_rad), s = std::sin(h.theta_rad);
    const Eigen::Vector2d t = p_field - Eigen::Vector2d(c * p_robot.x() - s * p_robot.y(),
                                                        s * p_robot.x() + c * p_robot.y());
    PoseHypothesis hyp;
    hyp.field_T_robot = Pose2(t.x(), t.y(), h.theta_rad);
    hyp.source = source;
    hyp.support = support;
    out.push_back(hyp);
  }
  return out;
}

}  // namespace houghloc
