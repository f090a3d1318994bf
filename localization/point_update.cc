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

/// The state the iterations solve for: the field pose (N = 3), or the field pose and the
/// frame's camera (roll, pitch) error (N = 5), a nuisance that is fitted with the pose and then
/// dropped. The recorded-pose fit, run on every hypothesis of every frame, solves 3 states: the
/// tracker's hot path does not pay for a tilt it does not fit.
constexpr int kPose = 3;
constexpr int kPoseAndTilt = 5;
template <int N>
using StateVector = Eigen::Matrix<double, N, 1>;
template <int N>
using StateMatrix = Eigen::Matrix<double, N, N>;

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
template <int N>
StateMatrix<N> stateCovariance(const Eigen::Matrix3d& pose_covariance,
                               const Eigen::Vector2d& tilt_sigma) {
  StateMatrix<N> c = StateMatrix<N>::Zero();
  c.template topLeftCorner<3, 3>() = pose_covariance;
  if constexpr (N == kPoseAndTilt) {
    c.template bottomRightCorner<2, 2>().diagonal() = tilt_sigma.cwiseProduct(tilt_sigma);
  }
  return c;
}

template <int N>
struct Accumulated {
  StateMatrix<N> jtj = StateMatrix<N>::Zero();
  StateVector<N> jtr = StateVector<N>::Zero();
  int used = 0;
  double weight_sum = 0.0;
  int processed = 0;  ///< valid points visited
  int inliers = 0;
  double log_likelihood_sum = 0.0;
};

/// One pass over the points at `pose` with the camera tilted by `tilt`: gated, robustly weighted
/// normal equations, and the likelihood statistics (ungated) used for hypothesis weights.
template <int N>
Accumulated<N> accumulate(const Pose2& pose, const Eigen::Vector2d& tilt,
                          const StateMatrix<N>& gate_cov, const std::vector<GroundPoint>& points,
                          const FeatureIndex& index, const PointUpdateConfig& cfg, size_t stride) {
  Accumulated<N> acc;
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
    Eigen::Vector2d q = gp.p_robot;
    if constexpr (N == kPoseAndTilt) q += usableTiltJacobian(gp) * tilt;
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
    StateVector<N> j;
    j.template head<2>() = a.normal;
    j(2) = -a.normal.x() * arm.y() + a.normal.y() * arm.x();
    if constexpr (N == kPoseAndTilt) {
      j.template tail<2>() = (rotation * usableTiltJacobian(gp)).transpose() * a.normal;
    }
    const double innovation_var = j.dot(gate_cov * j) + var;
    const double r2 = a.residual_m * a.residual_m;
    if (r2 > cfg.gate_chi2 * innovation_var) continue;
    const double w = gp.weight * robustWeight(r2 * inv_k2 / innovation_var, cfg.kernel);
    acc.jtj.template selfadjointView<Eigen::Lower>().rankUpdate(j, w);
    acc.jtr += (w * a.residual_m) * j;
    acc.weight_sum += w;
    ++acc.used;
  }
  acc.jtj = acc.jtj.template selfadjointView<Eigen::Lower>();
  return acc;
}

/// Iterated EKF of the pose; with N = 5, the camera's (roll, pitch) error is a nuisance of prior
/// std tilt_sigma (0: that angle is taken as exact). With N = 3, tilt_sigma is not read.
template <int N>
PointUpdateResult fitPose(const GaussianPose& prior, const std::vector<GroundPoint>& points,
                          const FeatureIndex& index, const PointUpdateConfig& cfg,
                          const Eigen::Vector2d& tilt_sigma) {
  PointUpdateResult result;
  result.posterior = prior;
  result.num_points = validPoints(points);
  const StateMatrix<N> prior_info =
      inverseOf<N>(stateCovariance<N>(prior.covariance, tilt_sigma.cwiseMax(1e-9)));
  // Angles taken as exact stay at zero (their tiny prior std leaves steps of ~1e-9 otherwise).
  const Eigen::Vector2d tilt_free = (tilt_sigma.array() > 0.0).cast<double>();
  const double inv_var = 1.0 / (cfg.point_sigma_m * cfg.point_sigma_m);
  // A wide prior starts where the points fit best along its axis (Gauss-Newton converges only
  // within about half a line spacing); the prior term below still pulls toward the mean.
  Pose2 x = searchUpdateStart(prior, points, index, cfg);
  Eigen::Vector2d tilt = Eigen::Vector2d::Zero();
  StateMatrix<N> gate_cov = stateCovariance<N>(prior.covariance, tilt_sigma);
  StateMatrix<N> info = prior_info;
  // Iterations run on an evenly strided subset (information is capped at max_effective_points
  // anyway); the last pass uses every point for the final step and the statistics.
  const size_t stride = static_cast<size_t>(
      std::ceil(points.size() / std::max(1.0, static_cast<double>(cfg.max_iteration_points))));
  const int max_iterations = std::max(1, cfg.max_iterations);
  Accumulated<N> acc;
  bool converged = false;
  for (int it = 0; it < max_iterations; ++it) {
    const bool final_pass = stride <= 1 || converged || it == max_iterations - 1;
    acc = accumulate<N>(x, tilt, gate_cov, points, index, cfg, final_pass ? 1 : stride);
    result.iterations = it + 1;
    if (acc.used < cfg.min_points) break;
    const double scale = std::min(1.0, cfg.max_effective_points / std::max(acc.weight_sum, 1e-9));
    info = prior_info + (scale * inv_var) * acc.jtj;
    StateVector<N> from_prior;
    from_prior.template head<3>() = poseDifference(prior.mean, x);
    if constexpr (N == kPoseAndTilt) from_prior.template tail<2>() = -tilt;
    const StateVector<N> rhs = prior_info * from_prior - (scale * inv_var) * acc.jtr;
    const StateVector<N> step = info.ldlt().solve(rhs);
    if (!step.allFinite()) break;
    x = poseAdd(x, step.template head<3>());
    if constexpr (N == kPoseAndTilt) tilt += step.template tail<2>().cwiseProduct(tilt_free);
    result.corrected = true;
    // Later iterations gate with the shrinking posterior, which rejects more outliers.
    gate_cov = inverseOf<N>(info);
    converged =
        step.template head<2>().norm() < cfg.converged_m && std::abs(step(2)) < cfg.converged_rad;
    // A hypothesis that explains few points is judged by its likelihood, not polished.
    converged = converged || acc.used < cfg.poor_association_share * acc.processed;
    if (converged && (stride <= 1 || final_pass)) break;
    if (final_pass && stride > 1) break;
  }
  if (result.corrected) {
    // The pose's marginal: the tilt is the frame's own and is not carried over.
    const Eigen::Matrix3d cov = inverseOf<N>(info).template topLeftCorner<3, 3>();
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
  PointUpdateResult rigid = fitPose<kPose>(prior, points, index, cfg, Eigen::Vector2d::Zero());
  if (tilt_sigma.isZero() || !(rigid.mean_log_likelihood < -cfg.tilt_min_gain)) return rigid;
  // Points that do not say how a tilt moves them (tilt_jacobian zero: not from a camera model;
  // or not finite) cannot show one.
  const bool tilt_observable = std::any_of(points.begin(), points.end(), [](const GroundPoint& p) {
    return !usableTiltJacobian(p).isZero();
  });
  if (!tilt_observable) return rigid;
  PointUpdateResult tilted = fitPose<kPoseAndTilt>(prior, points, index, cfg, tilt_sigma);
  return tilted.mean_log_likelihood >= rigid.mean_log_likelihood + cfg.tilt_min_gain ? tilted
                                                                                     : rigid;
}

}  // namespace houghloc
