#include "vision/camera_pose_corrector.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <utility>

namespace houghloc {
namespace {

Pose3 withCorrection(Pose3 pose, const Eigen::Vector2d& correction) {
  pose.roll += correction.x();
  pose.pitch += correction.y();
  return pose;
}

/// Ground direction (rad) of each segment under a camera pose; NaN when an end leaves the ground.
std::vector<double> directions(const std::vector<const GroundSegment*>& segments,
                               const Pose3& pose) {
  GroundProjectionConfig unlimited;
  unlimited.max_range_m = 1e9;
  unlimited.min_depression_rad = 0.0;
  std::vector<double> angles;
  for (const GroundSegment* s : segments) {
    const auto a = rayToGround(s->ray_a_camera, pose, unlimited);
    const auto b = rayToGround(s->ray_b_camera, pose, unlimited);
    angles.push_back(a && b ? std::atan2(b->y() - a->y(), b->x() - a->x()) : std::nan(""));
  }
  return angles;
}

/// Deviation (rad) of two undirected segment directions from parallel or perpendicular, whichever
/// is nearer: the difference wrapped into [-pi/4, pi/4).
double pairResidual(double angle_a, double angle_b) {
  constexpr double kQuarter = 0.25 * 3.14159265358979323846;
  const double d = angle_a - angle_b;
  return d - 2.0 * kQuarter * std::floor((d + kQuarter) / (2.0 * kQuarter));
}

}  // namespace

double CameraPoseCorrector::directionSigma(const GroundSegment& segment) const {
  // Least-squares line through n points spread over length L: sigma_angle ~ sigma sqrt(12 / n) / L.
  const double sigma = std::max(segment.rms_m, config_.min_point_sigma_m);
  return sigma * std::sqrt(12.0 / std::max(2, segment.num_points)) /
         std::max(0.1, segment.length());
}

Pose3 CameraPoseCorrector::corrected(const Pose3& recorded) const {
  return config_.enabled ? withCorrection(recorded, estimate_) : recorded;
}

void CameraPoseCorrector::reset() {
  estimate_.setZero();
  information_.setZero();
}

bool CameraPoseCorrector::update(const std::vector<GroundSegment>& segments,
                                 const Pose3& recorded) {
  if (!config_.enabled) return false;
  std::vector<const GroundSegment*> used;
  for (const GroundSegment& s : segments) {
    if (s.length() >= config_.min_segment_length_m && s.rms_m <= config_.max_segment_rms_m) {
      used.push_back(&s);
    }
  }
  if (used.size() < 2) return false;
  // Pairs that are field-line pairs under the current estimate.
  const std::vector<double> start = directions(used, withCorrection(recorded, estimate_));
  std::vector<std::pair<size_t, size_t>> pairs;
  std::vector<double> weights;
  const double max_residual = config_.max_pair_angle_rad;
  for (size_t i = 0; i < used.size(); ++i) {
    for (size_t j = i + 1; j < used.size(); ++j) {
      if (!std::isfinite(start[i]) || !std::isfinite(start[j])) continue;
      if (std::abs(pairResidual(start[i], start[j])) > max_residual) continue;
      pairs.emplace_back(i, j);
      weights.push_back(1.0 / std::hypot(directionSigma(*used[i]), directionSigma(*used[j])));
    }
  }
  if (pairs.empty()) return false;

  const Eigen::Matrix2d prior =
      config_.forgetting * information_ +
      Eigen::Matrix2d::Identity() / (config_.step_sigma_rad * config_.step_sigma_rad);
  const auto residuals = [&](const Eigen::Vector2d& c) {
    const std::vector<double> angles = directions(used, withCorrection(recorded, c));
    Eigen::VectorXd r(static_cast<long>(pairs.size()));
    for (size_t k = 0; k < pairs.size(); ++k) {
      const double res = pairResidual(angles[pairs[k].first], angles[pairs[k].second]);
      r(static_cast<long>(k)) = std::isfinite(res) ? weights[k] * res : 0.0;
    }
    return r;
  };
  // Huber weights from the residuals at the start of each Gauss-Newton step (IRLS).
  const auto robust = [&](const Eigen::VectorXd& r_unweighted) {
    Eigen::VectorXd w(r_unweighted.size());
    for (long k = 0; k < w.size(); ++k) {
      const double angle = std::abs(r_unweighted(k)) / weights[static_cast<size_t>(k)];
      w(k) = angle <= config_.huber_rad ? 1.0 : std::sqrt(config_.huber_rad / angle);
    }
    return w;
  };
  Eigen::Vector2d c = estimate_;
  Eigen::Matrix2d jtj = Eigen::Matrix2d::Zero();
  for (int it = 0; it < config_.iterations; ++it) {
    const Eigen::VectorXd raw = residuals(c);
    const Eigen::VectorXd w = robust(raw);
    const Eigen::VectorXd r0 = w.cwiseProduct(raw);
    Eigen::MatrixXd jac(r0.size(), 2);
    constexpr double kStep = 1e-4;
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d dc = Eigen::Vector2d::Zero();
      dc(k) = kStep;
      jac.col(k) = w.cwiseProduct(residuals(c + dc) - raw) / kStep;
    }
    jtj = jac.transpose() * jac;
    const Eigen::Matrix2d h = jtj + prior;
    const Eigen::Vector2d g = jac.transpose() * r0 + prior * (c - estimate_);
    const Eigen::Vector2d step = -h.ldlt().solve(g);
    if (!step.allFinite()) return false;
    c += step;
    if (step.norm() < 1e-6) break;
  }
  const double limit = config_.max_correction_rad;
  estimate_ = c.cwiseMax(-limit).cwiseMin(limit);
  information_ = config_.forgetting * information_ + jtj;
  const double scale = information_.trace() / config_.max_information;
  if (scale > 1.0) information_ /= scale;
  return true;
}

}  // namespace houghloc
