#include "vision/camera_pose_corrector.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace houghloc {
namespace {

constexpr double kQuarterTurn = 0.5 * 3.14159265358979323846;

Pose3 withCorrection(Pose3 pose, const Eigen::Vector2d& correction) {
  pose.roll += correction.x();
  pose.pitch += correction.y();
  return pose;
}

/// Angle wrapped into [-pi/4, pi/4): the deviation from the nearest field direction.
double wrapQuarter(double angle) {
  return angle - kQuarterTurn * std::floor((angle + 0.5 * kQuarterTurn) / kQuarterTurn);
}

}  // namespace

double CameraPoseCorrector::directionSigma(const GroundSegment& segment) const {
  // Least-squares line through n points spread over length L: sigma_angle ~ sigma sqrt(12 / n) / L.
  const double sigma = std::max(segment.rms_m, config_.min_point_sigma_m);
  return sigma * std::sqrt(12.0 / std::max(2, segment.num_points)) /
         std::max(0.1, segment.length());
}

Pose3 CameraPoseCorrector::corrected(const Pose3& recorded) const {
  return config_.enabled ? withCorrection(recorded, applied_) : recorded;
}

void CameraPoseCorrector::reset() {
  estimate_.setZero();
  applied_.setZero();
  frames_.clear();
}

Eigen::VectorXd CameraPoseCorrector::residuals(const Eigen::Vector2d& c,
                                               std::vector<double>* weights) const {
  GroundProjectionConfig unlimited;
  unlimited.max_range_m = 1e9;
  unlimited.min_depression_rad = 0.0;
  const bool compute_weights = weights->empty();
  std::vector<double> out;
  std::vector<double> angles;
  size_t index = 0;
  for (const Frame& frame : frames_) {
    const Pose3 pose = withCorrection(frame.recorded, c);
    angles.clear();
    double cos_sum = 0.0, sin_sum = 0.0;
    for (const Observation& o : frame.observations) {
      const auto a = rayToGround(o.ray_a, pose, unlimited);
      const auto b = rayToGround(o.ray_b, pose, unlimited);
      const double angle = a && b ? std::atan2(b->y() - a->y(), b->x() - a->x()) : std::nan("");
      angles.push_back(angle);
      if (!std::isfinite(angle)) continue;
      // Field directions repeat every 90 deg: average 4 x angle on the circle.
      const double w = 1.0 / (o.sigma_rad * o.sigma_rad);
      cos_sum += w * std::cos(4.0 * angle);
      sin_sum += w * std::sin(4.0 * angle);
    }
    const double heading = 0.25 * std::atan2(sin_sum, cos_sum);
    for (size_t i = 0; i < angles.size(); ++i, ++index) {
      const double r = wrapQuarter(angles[i] - heading);
      const double whitened = std::isfinite(r) ? r / frame.observations[i].sigma_rad : 0.0;
      if (compute_weights) {
        const double k = config_.huber_sigmas;
        const bool gated = !std::isfinite(r) || std::abs(r) > config_.max_residual_rad;
        weights->push_back(
            gated ? 0.0 : (std::abs(whitened) <= k ? 1.0 : std::sqrt(k / std::abs(whitened))));
      }
      out.push_back((*weights)[index] * whitened);
    }
  }
  return Eigen::Map<const Eigen::VectorXd>(out.data(), static_cast<long>(out.size()));
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
  std::sort(used.begin(), used.end(), [](const GroundSegment* a, const GroundSegment* b) {
    return a->length() > b->length();
  });
  used.resize(
      std::min(used.size(), static_cast<size_t>(std::max(0, config_.max_segments_per_frame))));
  // A frame with one direction and one segment says nothing (its heading absorbs it).
  if (used.size() >= 2) {
    Frame frame{recorded, {}};
    for (const GroundSegment* s : used) {
      frame.observations.push_back({s->ray_a_camera, s->ray_b_camera, directionSigma(*s)});
    }
    frames_.push_back(std::move(frame));
  }
  while (static_cast<int>(frames_.size()) > std::max(1, config_.window_frames)) frames_.pop_front();
  if (frames_.empty()) return false;

  // Gauss-Newton with IRLS weights fixed per step; the prior keeps unobserved directions at 0.
  const double prior = 1.0 / (config_.prior_sigma_rad * config_.prior_sigma_rad);
  Eigen::Vector2d c = estimate_;
  for (int it = 0; it < config_.iterations; ++it) {
    std::vector<double> weights;
    const Eigen::VectorXd r0 = residuals(c, &weights);
    Eigen::MatrixXd jacobian(r0.size(), 2);
    constexpr double kStep = 1e-5;
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d dc = Eigen::Vector2d::Zero();
      dc(k) = kStep;
      jacobian.col(k) = (residuals(c + dc, &weights) - r0) / kStep;
    }
    const Eigen::Matrix2d h = jacobian.transpose() * jacobian + prior * Eigen::Matrix2d::Identity();
    const Eigen::Vector2d g = jacobian.transpose() * r0 + prior * c;
    const Eigen::Vector2d step = -h.ldlt().solve(g);
    if (!step.allFinite()) return false;
    c += step;
    if (step.norm() < 1e-7) break;
  }
  const double limit = config_.max_correction_rad;
  estimate_ = c.cwiseMax(-limit).cwiseMin(limit);
  const bool enough = static_cast<int>(frames_.size()) >= config_.min_frames;
  for (int k = 0; k < 2; ++k) {
    applied_(k) = enough && std::abs(estimate_(k)) >= config_.min_applied_rad ? estimate_(k) : 0.0;
  }
  return true;
}

}  // namespace houghloc
