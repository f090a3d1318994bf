#include "localization/pose_refinement.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace houghloc {
namespace {

struct NormalEquations {
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  double sum_wr2 = 0.0, sum_w = 0.0;
};

NormalEquations accumulate(const WeightedPoints& points, const Pose2& pose,
                           const FeatureLookup& features, const RefinementConfig& config) {
  NormalEquations eq;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d& p = points.points[i];
    const Eigen::Vector2d rp(c * p.x() - s * p.y(), s * p.x() + c * p.y());
    const FeatureLookup::Residual r = features.residual(rp + pose.translation());
    if (!r.valid || std::abs(r.distance_m) > config.max_distance_m) continue;
    const double abs_r = std::abs(r.distance_m);
    const double huber = abs_r <= config.huber_m ? 1.0 : config.huber_m / abs_r;
    const double w = points.weights[i] * huber;
    // d p_field / d theta = Rz(theta + pi/2) p = (-rp.y, rp.x).
    const Eigen::Vector3d j(r.direction.x(), r.direction.y(),
                            r.direction.dot(Eigen::Vector2d(-rp.y(), rp.x())));
    eq.h += w * j * j.transpose();
    eq.b += w * j * r.distance_m;
    eq.sum_wr2 += w * r.distance_m * r.distance_m;
    eq.sum_w += w;
  }
  return eq;
}

}  // namespace

RefinementResult refinePose(const WeightedPoints& points, const Pose2& initial,
                            const FeatureLookup& features, const RefinementConfig& config,
                            const Eigen::Vector2d& frozen_direction) {
  RefinementResult out;
  out.field_T_robot = initial;
  Eigen::Matrix3d frozen = Eigen::Matrix3d::Zero();
  if (frozen_direction.squaredNorm() > 0.0) {
    frozen.topLeftCorner<2, 2>() = 1e6 * frozen_direction * frozen_direction.transpose();
  }
  const Eigen::Matrix3d prior =
      Eigen::Vector3d(1.0 / (config.prior_sigma_m * config.prior_sigma_m),
                      1.0 / (config.prior_sigma_m * config.prior_sigma_m),
                      1.0 / (config.prior_sigma_rad * config.prior_sigma_rad))
          .asDiagonal();
  NormalEquations eq;
  for (int it = 0; it < config.iterations; ++it) {
    eq = accumulate(points, out.field_T_robot, features, config);
    if (eq.sum_w <= 0.0) break;
    // Small damping (Levenberg) keeps the step bounded where the points leave a direction
    // unconstrained; `frozen` pins the direction along parallel lines.
    const Eigen::Matrix3d a = eq.h + 1e-3 * eq.sum_w * prior + frozen;
    const Eigen::Vector3d delta = -a.ldlt().solve(eq.b);
    if (!delta.allFinite()) break;
    const Pose2& p = out.field_T_robot;
    out.field_T_robot = Pose2(p.x + delta.x(), p.y + delta.y(), p.theta + delta.z());
    if (delta.head<2>().norm() + std::abs(delta.z()) < config.converged_m) break;
  }
  eq = accumulate(points, out.field_T_robot, features, config);
  out.information = eq.h;
  out.inlier_weight = eq.sum_w;
  out.rms_m = eq.sum_w > 0.0 ? std::sqrt(eq.sum_wr2 / eq.sum_w) : 0.0;
  const double sigma = std::max(out.rms_m, config.sigma_floor_m);
  const double scale =
      eq.sum_w > config.effective_points ? config.effective_points / eq.sum_w : 1.0;
  const Eigen::Matrix3d info = eq.h * (scale / (sigma * sigma)) + prior;
  out.covariance = info.inverse();
  return out;
}

}  // namespace houghloc
