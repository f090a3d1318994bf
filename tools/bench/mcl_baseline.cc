#include "tools/bench/mcl_baseline.h"

#include <algorithm>
#include <cmath>

namespace houghloc::bench {

MonteCarloLocalizer::MonteCarloLocalizer(const FieldModel& field, const DistanceGrid& grid,
                                         const MclConfig& config, std::uint32_t seed)
    : field_(field), grid_(grid), config_(config), rng_(seed) {
  // As teams do: the point likelihood is tabulated once per map on the distance grid's nodes, so
  // weighting a particle costs one lookup per point.
  const double sigma2 = config_.point_sigma_m * config_.point_sigma_m;
  log_field_.resize(static_cast<size_t>(grid_.cols()) * grid_.rows());
  for (int r = 0; r < grid_.rows(); ++r) {
    for (int c = 0; c < grid_.cols(); ++c) {
      const double d = grid_.distance(grid_.origin() + grid_.resolution() * Eigen::Vector2d(c, r));
      log_field_[static_cast<size_t>(r) * grid_.cols() + c] = static_cast<float>(
          std::log((1.0 - config_.z_random) * std::exp(-0.5 * d * d / sigma2) + config_.z_random));
    }
  }
  log_outside_ = std::log(config_.z_random);
}

double MonteCarloLocalizer::logLikelihoodAt(double x, double y) const {
  const double inv = 1.0 / grid_.resolution();
  const int c = static_cast<int>(std::lround((x - grid_.origin().x()) * inv));
  const int r = static_cast<int>(std::lround((y - grid_.origin().y()) * inv));
  if (c < 0 || r < 0 || c >= grid_.cols() || r >= grid_.rows()) return log_outside_;
  return log_field_[static_cast<size_t>(r) * grid_.cols() + c];
}

Pose2 MonteCarloLocalizer::randomPose() {
  std::uniform_real_distribution<double> ux(-field_.halfLength(), field_.halfLength());
  std::uniform_real_distribution<double> uy(-field_.halfWidth(), field_.halfWidth());
  std::uniform_real_distribution<double> ut(-M_PI, M_PI);
  return Pose2(ux(rng_), uy(rng_), ut(rng_));
}

void MonteCarloLocalizer::reset(const Pose2& pose, double sigma_m, double sigma_rad) {
  std::normal_distribution<double> n(0.0, 1.0);
  particles_.assign(config_.num_particles, Particle{});
  for (Particle& p : particles_) {
    p.pose = Pose2(pose.x + sigma_m * n(rng_), pose.y + sigma_m * n(rng_),
                   pose.theta + sigma_rad * n(rng_));
  }
  estimate_ = pose;
  covariance_ =
      Eigen::Vector3d(sigma_m * sigma_m, sigma_m * sigma_m, sigma_rad * sigma_rad).asDiagonal();
}

void MonteCarloLocalizer::resetUniform() {
  particles_.assign(config_.num_particles, Particle{});
  for (Particle& p : particles_) p.pose = randomPose();
  estimate_ = Pose2();
  covariance_ = Eigen::Vector3d(field_.halfLength() * field_.halfLength(),
                                field_.halfWidth() * field_.halfWidth(), M_PI * M_PI)
                    .asDiagonal();
}

void MonteCarloLocalizer::update(const Pose2& motion, const GroundPoints& points) {
  std::normal_distribution<double> n(0.0, 1.0);
  const double trans = std::hypot(motion.x, motion.y), rot = std::abs(motion.theta);
  const double st = std::sqrt(config_.trans_var_per_m * trans + config_.trans_var_per_rad * rot) +
                    config_.min_trans_noise_m;
  const double sr = std::sqrt(config_.rot_var_per_rad * rot + config_.rot_var_per_m * trans) +
                    config_.min_rot_noise_rad;
  const double scale =
      points.empty() ? 0.0 : config_.likelihood_points / static_cast<double>(points.size());
  double max_log = -1e300, mean_likelihood = 0.0;
  for (Particle& p : particles_) {
    p.pose = p.pose *
             Pose2(motion.x + st * n(rng_), motion.y + st * n(rng_), motion.theta + sr * n(rng_));
    double log_l = 0.0;
    const double c = std::cos(p.pose.theta), s = std::sin(p.pose.theta);
    for (const GroundPoint& gp : points.points) {
      const Eigen::Vector2d& q = gp.p_robot;
      log_l += logLikelihoodAt(c * q.x() - s * q.y() + p.pose.x, s * q.x() + c * q.y() + p.pose.y);
    }
    p.log_weight = scale * log_l;
    max_log = std::max(max_log, p.log_weight);
    mean_likelihood += std::exp(p.log_weight) / particles_.size();
  }
  if (points.empty()) {
    // Nothing weighs the particles: follow the estimate with odometry and average around it.
    estimate_ = estimate_ * motion;
    weights_.assign(particles_.size(), 1.0);
    computeEstimate(estimate_);
    return;
  }
  // Augmented MCL: inject random particles when the short-term likelihood drops below the
  // long-term one.
  w_slow_ += config_.alpha_slow * (mean_likelihood - w_slow_);
  w_fast_ += config_.alpha_fast * (mean_likelihood - w_fast_);
  const double inject =
      w_slow_ > 0.0 ? std::clamp(1.0 - w_fast_ / w_slow_, 0.0, config_.max_injection) : 0.0;
  weights_.resize(particles_.size());
  for (size_t i = 0; i < particles_.size(); ++i) {
    weights_[i] = std::exp(particles_[i].log_weight - max_log);
  }
  computeEstimate(heaviestClusterCentre());
  resample(inject);
}

void MonteCarloLocalizer::resample(double inject_share) {
  double sum = 0.0;
  for (double w : weights_) sum += w;
  if (!(sum > 0.0)) return;
  const int n = static_cast<int>(particles_.size());
  std::vector<Particle> next;
  next.reserve(n);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const int injected = static_cast<int>(inject_share * n);
  const int drawn = n - injected;
  // Low-variance (systematic) resampling: one random offset, equally spaced pointers.
  const double step = sum / drawn;
  double pointer = u01(rng_) * step, cumulative = weights_[0];
  int i = 0;
  for (int m = 0; m < drawn; ++m) {
    while (pointer > cumulative && i < n - 1) cumulative += weights_[++i];
    next.push_back(particles_[i]);
    pointer += step;
  }
  for (int m = 0; m < injected; ++m) next.push_back(Particle{randomPose(), 0.0});
  particles_ = std::move(next);
}

bool MonteCarloLocalizer::inCluster(const Pose2& p, const Pose2& centre) const {
  return std::hypot(p.x - centre.x, p.y - centre.y) <= config_.cluster_radius_m &&
         std::abs(angleDifference(p.theta, centre.theta)) <= config_.cluster_heading_rad;
}

Pose2 MonteCarloLocalizer::heaviestClusterCentre() const {
  std::vector<size_t> order(particles_.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  const size_t k = std::min(order.size(), static_cast<size_t>(config_.cluster_candidates));
  std::partial_sort(order.begin(), order.begin() + k, order.end(),
                    [&](size_t a, size_t b) { return weights_[a] > weights_[b]; });
  Pose2 centre = particles_[order[0]].pose;
  double heaviest = -1.0;
  for (size_t c = 0; c < k; ++c) {
    const Pose2& candidate = particles_[order[c]].pose;
    double mass = 0.0;
    for (size_t i = 0; i < particles_.size(); ++i) {
      if (inCluster(particles_[i].pose, candidate)) mass += weights_[i];
    }
    if (mass > heaviest) {
      heaviest = mass;
      centre = candidate;
    }
  }
  return centre;
}

void MonteCarloLocalizer::computeEstimate(const Pose2& centre) {
  double sw = 0.0, sx = 0.0, sy = 0.0, sc = 0.0, ss = 0.0;
  for (size_t i = 0; i < particles_.size(); ++i) {
    const Pose2& p = particles_[i].pose;
    if (!inCluster(p, centre)) continue;
    const double w = weights_[i];
    sw += w;
    sx += w * p.x;
    sy += w * p.y;
    sc += w * std::cos(p.theta);
    ss += w * std::sin(p.theta);
  }
  if (!(sw > 0.0)) return;
  estimate_ = Pose2(sx / sw, sy / sw, std::atan2(ss, sc));
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < particles_.size(); ++i) {
    const Pose2& p = particles_[i].pose;
    if (!inCluster(p, centre)) continue;
    const Eigen::Vector3d d(p.x - estimate_.x, p.y - estimate_.y,
                            angleDifference(p.theta, estimate_.theta));
    cov += (weights_[i] / sw) * d * d.transpose();
  }
  // A floor keeps the covariance positive definite when the cluster is a single particle.
  covariance_ = cov + Eigen::Vector3d(1e-6, 1e-6, 1e-6).asDiagonal().toDenseMatrix();
}

}  // namespace houghloc::bench
