#include "localization/frame_tilt.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace houghloc {
namespace {

/// log prior weight + likelihood_points x mean per-point log-likelihood + the tilt's log prior.
double posteriorScore(const GaussianPose& prior, const PointUpdateResult& result,
                      const Eigen::Vector2d& tilt_sigma, double likelihood_points) {
  double tilt_log_prior = 0.0;
  for (int i = 0; i < 2; ++i) {
    if (tilt_sigma(i) > 0.0) tilt_log_prior -= 0.5 * std::pow(result.tilt(i) / tilt_sigma(i), 2);
  }
  const double weight = std::max(prior.weight, std::numeric_limits<double>::min());
  return std::log(weight) + likelihood_points * result.mean_log_likelihood + tilt_log_prior;
}

}  // namespace

std::vector<GroundPoint> pointsWithTilt(const std::vector<GroundPoint>& points,
                                        const Eigen::Vector2d& tilt) {
  std::vector<GroundPoint> moved = points;
  for (GroundPoint& p : moved) p.p_robot += usableTiltJacobian(p) * tilt;
  return moved;
}

std::vector<PointUpdateResult> updateWithOneFrameTilt(const std::vector<GaussianPose>& priors,
                                                      const std::vector<GroundPoint>& points,
                                                      const FeatureIndex& index,
                                                      const PointUpdateConfig& config,
                                                      double likelihood_points) {
  std::vector<PointUpdateResult> results;
  results.reserve(priors.size());
  for (const GaussianPose& prior : priors) {
    results.push_back(updateWithGroundPoints(prior, points, index, config));
  }
  const bool any_tilted = std::any_of(results.begin(), results.end(),
                                      [](const PointUpdateResult& r) { return !r.tilt.isZero(); });
  if (!any_tilted) return results;

  const Eigen::Vector2d tilt_sigma(config.roll_sigma_rad, config.pitch_sigma_rad);
  size_t chosen = 0;
  double best_score = -std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < results.size(); ++k) {
    const double score = posteriorScore(priors[k], results[k], tilt_sigma, likelihood_points);
    if (score > best_score) {
      best_score = score;
      chosen = k;
    }
  }
  const Eigen::Vector2d frame_tilt = results[chosen].tilt;
  // Every other hypothesis at the frame's tilt, with the tilt held (a rigid fit of the points
  // as that camera sees them).
  PointUpdateConfig held = config;
  held.roll_sigma_rad = 0.0;
  held.pitch_sigma_rad = 0.0;
  const std::vector<GroundPoint> tilted = pointsWithTilt(points, frame_tilt);
  for (size_t k = 0; k < results.size(); ++k) {
    if (results[k].tilt == frame_tilt) continue;
    results[k] = updateWithGroundPoints(priors[k], tilted, index, held);
    results[k].tilt = frame_tilt;
  }
  return results;
}

}  // namespace houghloc
