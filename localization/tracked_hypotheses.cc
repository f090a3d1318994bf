#include "localization/tracked_hypotheses.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

namespace houghloc {

GaussianPose mergeGaussians(const GaussianPose& a, const GaussianPose& b) {
  const double wa = std::max(a.weight, 0.0), wb = std::max(b.weight, 0.0);
  const double w = wa + wb;
  const double fb = w > 0.0 ? wb / w : 0.5;
  const Eigen::Vector3d db = poseDifference(b.mean, a.mean);  // b relative to a
  GaussianPose out;
  out.mean = poseAdd(a.mean, fb * db);
  const Eigen::Vector3d da_mu = -fb * db, db_mu = (1.0 - fb) * db;  // each mean minus the merged
  out.covariance = (1.0 - fb) * (a.covariance + da_mu * da_mu.transpose()) +
                   fb * (b.covariance + db_mu * db_mu.transpose());
  out.weight = w;
  return out;
}

double mahalanobisSquared(const GaussianPose& a, const GaussianPose& b) {
  const Eigen::Vector3d d = poseDifference(a.mean, b.mean);
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(a.covariance + b.covariance);
  if (ldlt.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
  const double m = d.dot(ldlt.solve(d));
  return std::isfinite(m) && m >= 0.0 ? m : std::numeric_limits<double>::infinity();
}

void normalizeTrackedWeights(std::vector<TrackedHypothesis>* set) {
  double sum = 0.0;
  for (auto& h : *set) {
    if (!std::isfinite(h.pose.weight) || h.pose.weight < 0.0) h.pose.weight = 0.0;
    sum += h.pose.weight;
  }
  const bool usable = sum > 0.0 && std::isfinite(sum);
  for (auto& h : *set) h.pose.weight = usable ? h.pose.weight / sum : 1.0 / set->size();
}

void sortByWeight(std::vector<TrackedHypothesis>* set) {
  std::sort(set->begin(), set->end(), [](const TrackedHypothesis& a, const TrackedHypothesis& b) {
    if (a.pose.weight != b.pose.weight) return a.pose.weight > b.pose.weight;
    return a.id < b.id;
  });
}

void mergeConverged(const TrackedSetConfig& config, std::vector<TrackedHypothesis>* set) {
  sortByWeight(set);
  std::vector<TrackedHypothesis> kept;
  for (const TrackedHypothesis& h : *set) {
    bool merged = false;
    for (TrackedHypothesis& k : kept) {
      const Eigen::Vector3d d = poseDifference(h.pose.mean, k.pose.mean);
      const double dist = d.head<2>().norm(), angle = std::abs(d.z());
      const bool close = dist < config.merge_distance_m && angle < config.merge_angle_rad;
      const bool within = dist < config.merge_max_distance_m && angle < config.merge_max_angle_rad;
      if (close || (within && mahalanobisSquared(h.pose, k.pose) < config.merge_chi2)) {
        k.pose = mergeGaussians(k.pose, h.pose);
        k.age_frames = std::max(k.age_frames, h.age_frames);
        merged = true;
        break;
      }
    }
    if (!merged) kept.push_back(h);
  }
  *set = std::move(kept);
}

void pruneWeak(const TrackedSetConfig& config, std::vector<TrackedHypothesis>* set) {
  normalizeTrackedWeights(set);
  sortByWeight(set);
  if (set->empty()) return;
  const double threshold = set->front().pose.weight * config.prune_relative_weight;
  set->erase(std::remove_if(set->begin() + 1, set->end(),
                            [&](const TrackedHypothesis& h) {
                              // Newcomers are judged by one frame of points before they can go.
                              return h.age_frames > 0 && h.pose.weight < threshold;
                            }),
             set->end());
  if (static_cast<int>(set->size()) > config.max_hypotheses) {
    set->resize(static_cast<size_t>(std::max(config.max_hypotheses, 1)));
  }
  normalizeTrackedWeights(set);
}

bool areMirrors(const Pose2& a, const Pose2& b, double tolerance_m, double tolerance_rad) {
  const Eigen::Vector3d d = poseDifference(mirrored(a), b);
  return d.head<2>().norm() <= tolerance_m && std::abs(d.z()) <= tolerance_rad;
}

double mirrorTwinWeight(const std::vector<GaussianPose>& best_first, double tolerance_m,
                        double tolerance_rad) {
  double sum = 0.0;
  for (const GaussianPose& p : best_first) {
    if (areMirrors(best_first.front().mean, p.mean, tolerance_m, tolerance_rad)) {
      sum += std::max(0.0, p.weight);
    }
  }
  return sum;
}

}  // namespace houghloc
