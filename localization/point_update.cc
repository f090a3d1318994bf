#include "localization/point_update.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "localization/point_update_search.h"

namespace houghloc {
namespace {

/// IRLS weight for a squared residual in units of the kernel scale (u2 = (r / scale)^2).
/// Huber: 1 inside, 1 / |u| outside. Cauchy: 1 / (1 + u^2). Squared, so no sqrt per point.
double robustWeight(double u2, PointUpdateConfig::Kernel kernel) {
  if (kernel == PointUpdateConfig::Kernel::kHuber) return u2 <= 1.0 ? 1.0 : 1.0 / std::sqrt(u2);
  return 1.0 / (1.0 + u2);
}

/// Information matrix of a covariance, regularised so a singular or huge covariance still gives a
/// usable (tiny) prior instead of NaN.
Eigen::Matrix3d informationOf(const Eigen::Matrix3d& covariance) {
  Eigen::Matrix3d p = 0.5 * (covariance + covariance.transpose());
  p.diagonal().array() += 1e-12;
  Eigen::LDLT<Eigen::Matrix3d> ldlt(p);
  Eigen::Matrix3d info = ldlt.solve(Eigen::Matrix3d::Identity());
  if (ldlt.info() != Eigen::Success || !info.allFinite()) {
    info = p.diagonal().cwiseMax(1e-12).cwiseInverse().asDiagonal();
  }
  return 0.5 * (info + info.transpose());
}

struct Accumulated {
  Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
  Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
  int used = 0;
  double weight_sum = 0.0;
  int processed = 0;  ///< valid points visited
  int inliers = 0;
  double log_likelihood_sum = 0.0;
};

/// One pass over the points at `pose`: gated, robustly weighted normal equations, and the
/// likelihood statistics (ungated) used for hypothesis weights.
Accumulated accumulate(const Pose2& pose, const Eigen::Matrix3d& gate_cov,
                       const std::vector<GroundPoint>& points, const FeatureIndex& index,
                       const PointUpdateConfig& cfg, size_t stride) {
  Accumulated acc;
  const double var = cfg.point_sigma_m * cfg.point_sigma_m;
  const double inv_lik_var = 1.0 / (cfg.likelihood_sigma_m * cfg.likelihood_sigma_m);
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double inv_k2 = 1.0 / (cfg.kernel_sigmas * cfg.kernel_sigmas);
  const double g00 = gate_cov(0, 0), g01 = gate_cov(0, 1), g02 = gate_cov(0, 2);
  const double g11 = gate_cov(1, 1), g12 = gate_cov(1, 2), g22 = gate_cov(2, 2);
  double h00 = 0.0, h01 = 0.0, h02 = 0.0, h11 = 0.0, h12 = 0.0, h22 = 0.0;
  for (size_t i = 0; i < points.size(); i += stride) {
    const GroundPoint& gp = points[i];
    const Eigen::Vector2d& q = gp.p_robot;
    if (!q.allFinite() || !(gp.weight > 0.0) || !std::isfinite(gp.weight)) continue;
    ++acc.processed;
    const Eigen::Vector2d arm(c * q.x() - s * q.y(), s * q.x() + c * q.y());
    const Eigen::Vector2d p = arm + Eigen::Vector2d(pose.x, pose.y);
    Association a;
    if (!index.associate(p, &a)) {
      acc.log_likelihood_sum -= 0.5 * cfg.outlier_chi2;
      continue;
    }
    acc.log_likelihood_sum -=
        0.5 * std::min(a.distance_m * a.distance_m * inv_lik_var, cfg.outlier_chi2);
    if (a.distance_m <= cfg.inlier_m) ++acc.inliers;
    if (a.distance_m > cfg.max_association_m) continue;
    // d p / d theta = Rz'(theta) q = perp(arm).
    const double j0 = a.normal.x(), j1 = a.normal.y();
    const double j2 = -j0 * arm.y() + j1 * arm.x();
    // J P J^T written out for the symmetric 3x3 P: this loop is the tracker's hot path.
    const double innovation_var = g00 * j0 * j0 + g11 * j1 * j1 + g22 * j2 * j2 +
                                  2.0 * (g01 * j0 * j1 + g02 * j0 * j2 + g12 * j1 * j2) + var;
    const double r2 = a.residual_m * a.residual_m;
    if (r2 > cfg.gate_chi2 * innovation_var) continue;
    const double w = gp.weight * robustWeight(r2 * inv_k2 / innovation_var, cfg.kernel);
    const double wr = w * a.residual_m;
    h00 += w * j0 * j0;
    h01 += w * j0 * j1;
    h02 += w * j0 * j2;
    h11 += w * j1 * j1;
    h12 += w * j1 * j2;
    h22 += w * j2 * j2;
    acc.jtr += Eigen::Vector3d(wr * j0, wr * j1, wr * j2);
    acc.weight_sum += w;
    ++acc.used;
  }
  acc.jtj << h00, h01, h02, h01, h11, h12, h02, h12, h22;
  return acc;
}

}  // namespace

PointUpdateResult updateWithGroundPoints(const GaussianPose& prior,
                                         const std::vector<GroundPoint>& points,
                                         const FeatureIndex& index, const PointUpdateConfig& cfg) {
  PointUpdateResult result;
  result.posterior = prior;
  for (const GroundPoint& gp : points) result.num_points += gp.p_robot.allFinite() ? 1 : 0;
  if (!prior.isFinite() || index.empty() || !(cfg.point_sigma_m > 0.0) ||
      !(cfg.likelihood_sigma_m > 0.0)) {
    return result;
  }
  const Eigen::Matrix3d prior_info = informationOf(prior.covariance);
  const double inv_var = 1.0 / (cfg.point_sigma_m * cfg.point_sigma_m);
  // A wide prior starts where the points fit best along its axis (Gauss-Newton converges only
  // within about half a line spacing); the prior term below still pulls toward the mean.
  Pose2 x = searchUpdateStart(prior, points, index, cfg);
  Eigen::Matrix3d gate_cov = prior.covariance;
  Eigen::Matrix3d info = prior_info;
  // Iterations run on an evenly strided subset (information is capped at max_effective_points
  // anyway); the last pass uses every point for the final step and the statistics.
  const size_t stride = static_cast<size_t>(
      std::ceil(points.size() / std::max(1.0, static_cast<double>(cfg.max_iteration_points))));
  const int max_iterations = std::max(1, cfg.max_iterations);
  Accumulated acc;
  bool converged = false;
  for (int it = 0; it < max_iterations; ++it) {
    const bool final_pass = stride <= 1 || converged || it == max_iterations - 1;
    acc = accumulate(x, gate_cov, points, index, cfg, final_pass ? 1 : stride);
    result.iterations = it + 1;
    if (acc.used < cfg.min_points) break;
    const double scale = std::min(1.0, cfg.max_effective_points / std::max(acc.weight_sum, 1e-9));
    info = prior_info + (scale * inv_var) * acc.jtj;
    const Eigen::Vector3d rhs =
        prior_info * poseDifference(prior.mean, x) - (scale * inv_var) * acc.jtr;
    const Eigen::Vector3d step = info.ldlt().solve(rhs);
    if (!step.allFinite()) break;
    x = poseAdd(x, step);
    result.corrected = true;
    // Later iterations gate with the shrinking posterior, which rejects more outliers.
    gate_cov = informationOf(info);
    converged = step.head<2>().norm() < cfg.converged_m && std::abs(step.z()) < cfg.converged_rad;
    // A hypothesis that explains few points is judged by its likelihood, not polished.
    converged = converged || acc.used < cfg.poor_association_share * acc.processed;
    if (converged && (stride <= 1 || final_pass)) break;
    if (final_pass && stride > 1) break;
  }
  if (result.corrected) {
    const Eigen::Matrix3d cov = informationOf(info);
    if (x.isFinite() && cov.allFinite()) {
      result.posterior.mean = x;
      result.posterior.covariance = cov;
    } else {
      result.corrected = false;
    }
  }
  result.num_associated = acc.used;
  result.num_inliers = acc.inliers;
  if (acc.processed > 0) {
    result.inlier_share = static_cast<double>(acc.inliers) / acc.processed;
    result.mean_log_likelihood = acc.log_likelihood_sum / acc.processed;
  }
  return result;
}

}  // namespace houghloc
