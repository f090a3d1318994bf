#include "localization/point_update_search.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace houghloc {
namespace {

/// Sum of the truncated-Gaussian point log-likelihoods at `pose` over every `stride`-th point
/// (the statistic the weights use), and the number of points visited.
double pointLogLikelihood(const Pose2& pose, const std::vector<GroundPoint>& points,
                          const FeatureIndex& index, const PointUpdateConfig& cfg, size_t stride,
                          int* visited) {
  const double inv_var = 1.0 / (cfg.likelihood_sigma_m * cfg.likelihood_sigma_m);
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  double sum = 0.0;
  *visited = 0;
  for (size_t i = 0; i < points.size(); i += stride) {
    const GroundPoint& gp = points[i];
    const Eigen::Vector2d& q = gp.p_robot;
    if (!q.allFinite() || !(gp.weight > 0.0) || !std::isfinite(gp.weight)) continue;
    ++*visited;
    const Eigen::Vector2d p(pose.x + c * q.x() - s * q.y(), pose.y + s * q.x() + c * q.y());
    Association a;
    const double d2 = index.associate(p, &a) ? a.distance_m * a.distance_m * inv_var : 1e300;
    sum -= 0.5 * std::min(d2, cfg.outlier_chi2);
  }
  return sum;
}

}  // namespace

Pose2 searchUpdateStart(const GaussianPose& prior, const std::vector<GroundPoint>& points,
                        const FeatureIndex& index, const PointUpdateConfig& cfg) {
  if (cfg.search_max_starts <= 1 || !(cfg.search_step_m > 0.0)) return prior.mean;
  const Eigen::Matrix2d pp = 0.5 * (prior.covariance.topLeftCorner<2, 2>() +
                                    prior.covariance.topLeftCorner<2, 2>().transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(pp);
  if (eig.info() != Eigen::Success) return prior.mean;
  const double sigma = std::sqrt(std::max(0.0, eig.eigenvalues()(1)));
  if (!(sigma > cfg.search_min_sigma_m) || !std::isfinite(sigma)) return prior.mean;
  // A shift t along the axis moves the heading by its regression on the position (the
  // conditional mean of the prior); its prior chi^2 is (t / sigma)^2.
  const Eigen::Vector2d axis = eig.eigenvectors().col(1);
  const double dtheta_per_m =
      prior.covariance.block<1, 2>(2, 0).dot(axis) / std::max(sigma * sigma, 1e-12);
  const int half =
      std::min(cfg.search_max_starts / 2,
               static_cast<int>(std::floor(cfg.search_sigmas * sigma / cfg.search_step_m)));
  if (half < 1) return prior.mean;
  const size_t stride = static_cast<size_t>(
      std::ceil(points.size() / std::max(1.0, static_cast<double>(cfg.max_iteration_points))));
  Pose2 best_pose = prior.mean;
  double best_score = 0.0;
  for (int k = -half; k <= half; ++k) {
    const double t = k * cfg.search_step_m;
    const Pose2 start =
        poseAdd(prior.mean, Eigen::Vector3d(t * axis.x(), t * axis.y(),
                                            std::isfinite(dtheta_per_m) ? t * dtheta_per_m : 0.0));
    int visited = 0;
    const double log_likelihood = pointLogLikelihood(start, points, index, cfg, stride, &visited);
    if (visited == 0) return prior.mean;
    // Points along a line are correlated: at most max_effective_points count (as in the update).
    const double effective = std::min(static_cast<double>(visited), cfg.max_effective_points);
    const double score = effective * log_likelihood / visited - 0.5 * (t / sigma) * (t / sigma);
    if (k == -half || score > best_score + 1e-9 || (k == 0 && score >= best_score - 1e-9)) {
      best_score = score;
      best_pose = start;
    }
  }
  return best_pose;
}

}  // namespace houghloc
