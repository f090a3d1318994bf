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

/// The state the iterations solve for: the field pose and the frame's camera (roll, pitch)
/// error, a nuisance that is fitted with the pose and then dropped.
constexpr int kState = 5;
using StateVector = Eigen::Matrix<double, kState, 1>;
using StateMatrix = Eigen::Matrix<double, kState, kState>;

/// Inverse of a covariance or information matrix, regularised so a singular or huge one still
/// gives a usable (tiny) inverse instead of NaN.
template <int N>
Eigen::Matrix<double, N, N> inverseOf(const Eigen::Matrix<double, N, N>& m) {
  using Matrix = Eigen::Matrix<double, N, N>;
  Matrix p = 0.5 * (m + m.transpose());
  p.diagonal().array() += 1e-12;
  Eigen::LDLT<Matrix> ldlt(p);
  Matrix inverse = ldlt.solve(Matrix::Identity());
  if (ldlt.info() != Eigen::Success || !inverse.allFinite()) {
    inverse = p.diagonal().cwiseMax(1e-12).cwiseInverse().asDiagonal();
  }
  return 0.5 * (inverse + inverse.transpose());
}

int validPoints(const std::vector<GroundPoint>& points) {
  int n = 0;
  for (const GroundPoint& gp : points) n += gp.p_robot.allFinite() ? 1 : 0;
  return n;
}

/// Pose covariance and the tilt prior as one block-diagonal covariance of the state.
StateMatrix stateCovariance(const Eigen::Matrix3d& pose_covariance,
                            const Eigen::Vector2d& tilt_sigma) {
  StateMatrix c = StateMatrix::Zero();
  c.topLeftCorner<3, 3>() = pose_covariance;
  c.bottomRightCorner<2, 2>().diagonal() = tilt_sigma.cwiseProduct(tilt_sigma);
  return c;
}

struct Accumulated {
  StateMatrix jtj = StateMatrix::Zero();
  StateVector jtr = StateVector::Zero();
  int used = 0;
  double weight_sum = 0.0;
  int processed = 0;  ///< valid points visited
  int inliers = 0;
  double log_likelihood_sum = 0.0;
};

/// One pass over the points at `pose` with the camera tilted by `tilt`: gated, robustly weighted
/// normal equations, and the likelihood statistics (ungated) used for hypothesis weights.
Accumulated accumulate(const Pose2& pose, const Eigen::Vector2d& tilt, const StateMatrix& gate_cov,
                       const std::vector<GroundPoint>& points, const FeatureIndex& index,
                       const PointUpdateConfig& cfg, size_t stride) {
  Accumulated acc;
  const double var = cfg.point_sigma_m * cfg.point_sigma_m;
  const double inv_lik_var = 1.0 / (cfg.likelihood_sigma_m * cfg.likelihood_sigma_m);
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  Eigen::Matrix2d rotation;
  rotation << c, -s, s, c;
  const double inv_k2 = 1.0 / (cfg.kernel_sigmas * cfg.kernel_sigmas);
  for (size_t i = 0; i < points.size(); i += stride) {
    const GroundPoint& gp = points[i];
    if (!gp.p_robot.allFinite() || !(gp.weight > 0.0) || !std::isfinite(gp.weight)) continue;
    ++acc.processed;
    const Eigen::Vector2d q = gp.p_robot + gp.tilt_jacobian * tilt;
    const Eigen::Vector2d arm = rotation * q;
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
    // d p / d theta = Rz'(theta) q = perp(arm); d p / d tilt = Rz(theta) tilt_jacobian.
    StateVector j;
    j.head<2>() = a.normal;
    j(2) = -a.normal.x() * arm.y() + a.normal.y() * arm.x();
    j.tail<2>() = (rotation * gp.tilt_jacobian).transpose() * a.normal;
    const double innovation_var = j.dot(gate_cov * j) + var;
    const double r2 = a.residual_m * a.residual_m;
    if (r2 > cfg.gate_chi2 * innovation_var) continue;
    const double w = gp.weight * robustWeight(r2 * inv_k2 / innovation_var, cfg.kernel);
    acc.jtj.selfadjointView<Eigen::Lower>().rankUpdate(j, w);
    acc.jtr += (w * a.residual_m) * j;
    acc.weight_sum += w;
    ++acc.used;
  }
  acc.jtj = acc.jtj.selfadjointView<Eigen::Lower>();
  return acc;
}

/// Iterated EKF of the pose, with the camera's (roll, pitch) error as a nuisance of prior std
/// tilt_sigma (0: that angle is taken as exact).
PointUpdateResult fitPose(const GaussianPose& prior, const std::vector<GroundPoint>& points,
                          const FeatureIndex& index, const PointUpdateConfig& cfg,
                          const Eigen::Vector2d& tilt_sigma) {
  PointUpdateResult result;
  result.posterior = prior;
  result.num_points = validPoints(points);
  const StateMatrix prior_info =
      inverseOf<kState>(stateCovariance(prior.covariance, tilt_sigma.cwiseMax(1e-9)));
  // Angles taken as exact stay at zero (their tiny prior std leaves steps of ~1e-9 otherwise).
  const Eigen::Vector2d tilt_free = (tilt_sigma.array() > 0.0).cast<double>();
  const double inv_var = 1.0 / (cfg.point_sigma_m * cfg.point_sigma_m);
  // A wide prior starts where the points fit best along its axis (Gauss-Newton converges only
  // within about half a line spacing); the prior term below still pulls toward the mean.
  Pose2 x = searchUpdateStart(prior, points, index, cfg);
  Eigen::Vector2d tilt = Eigen::Vector2d::Zero();
  StateMatrix gate_cov = stateCovariance(prior.covariance, tilt_sigma);
  StateMatrix info = prior_info;
  // Iterations run on an evenly strided subset (information is capped at max_effective_points
  // anyway); the last pass uses every point for the final step and the statistics.
  const size_t stride = static_cast<size_t>(
      std::ceil(points.size() / std::max(1.0, static_cast<double>(cfg.max_iteration_points))));
  const int max_iterations = std::max(1, cfg.max_iterations);
  Accumulated acc;
  bool converged = false;
  for (int it = 0; it < max_iterations; ++it) {
    const bool final_pass = stride <= 1 || converged || it == max_iterations - 1;
    acc = accumulate(x, tilt, gate_cov, points, index, cfg, final_pass ? 1 : stride);
    result.iterations = it + 1;
    if (acc.used < cfg.min_points) break;
    const double scale = std::min(1.0, cfg.max_effective_points / std::max(acc.weight_sum, 1e-9));
    info = prior_info + (scale * inv_var) * acc.jtj;
    StateVector from_prior;
    from_prior << poseDifference(prior.mean, x), -tilt;
    const StateVector rhs = prior_info * from_prior - (scale * inv_var) * acc.jtr;
    const StateVector step = info.ldlt().solve(rhs);
    if (!step.allFinite()) break;
    x = poseAdd(x, step.head<3>());
    tilt += step.tail<2>().cwiseProduct(tilt_free);
    result.corrected = true;
    // Later iterations gate with the shrinking posterior, which rejects more outliers.
    gate_cov = inverseOf<kState>(info);
    converged = step.head<2>().norm() < cfg.converged_m && std::abs(step(2)) < cfg.converged_rad;
    // A hypothesis that explains few points is judged by its likelihood, not polished.
    converged = converged || acc.used < cfg.poor_association_share * acc.processed;
    if (converged && (stride <= 1 || final_pass)) break;
    if (final_pass && stride > 1) break;
  }
  if (result.corrected) {
    // The pose's marginal: the tilt is the frame's own and is not carried over.
    const Eigen::Matrix3d cov = inverseOf<kState>(info).topLeftCorner<3, 3>();
    if (x.isFinite() && cov.allFinite() && tilt.allFinite()) {
      result.posterior.mean = x;
      result.posterior.covariance = cov;
      result.tilt = tilt;
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

}  // namespace

PointUpdateResult updateWithGroundPoints(const GaussianPose& prior,
                                         const std::vector<GroundPoint>& points,
                                         const FeatureIndex& index, const PointUpdateConfig& cfg) {
  const Eigen::Vector2d tilt_sigma(cfg.roll_sigma_rad, cfg.pitch_sigma_rad);
  if (!prior.isFinite() || index.empty() || !(cfg.point_sigma_m > 0.0) ||
      !(cfg.likelihood_sigma_m > 0.0) || !(tilt_sigma.array() >= 0.0).all()) {
    PointUpdateResult unchanged;
    unchanged.posterior = prior;
    unchanged.num_points = validPoints(points);
    return unchanged;
  }
  // The recorded camera pose first. Only a frame it explains poorly is fitted again with the
  // tilt free, and the tilted fit is taken only when it explains the points clearly better:
  // the tilt adds freedom that noise would use too.
  PointUpdateResult rigid = fitPose(prior, points, index, cfg, Eigen::Vector2d::Zero());
  if (tilt_sigma.isZero() || !(rigid.mean_log_likelihood < -cfg.tilt_min_gain)) return rigid;
  PointUpdateResult tilted = fitPose(prior, points, index, cfg, tilt_sigma);
  return tilted.mean_log_likelihood >= rigid.mean_log_likelihood + cfg.tilt_min_gain ? tilted
                                                                                     : rigid;
}

}  // namespace houghloc
