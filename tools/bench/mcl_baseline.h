#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "field_models/distance_grid.h"
#include "field_models/field_model.h"
#include "field_models/ground_points.h"
#include "field_models/pose2.h"

namespace houghloc::bench {

/// A reference Monte Carlo localization as RoboCup teams use it (the tracker's baseline in
/// tools/bench only): particles moved by sampled odometry noise, weighted by a likelihood field
/// (the map's DistanceGrid), low-variance resampling, and random injection of uniform particles
/// when the average likelihood drops (augmented MCL, Thrun et al., Probabilistic Robotics 8.3.5).
struct MclConfig {
  int num_particles = 500;
  double point_sigma_m = 0.05;       ///< likelihood field std, m
  double z_random = 0.05;            ///< uniform share of the point likelihood (outliers)
  double likelihood_points = 30.0;   ///< a frame counts as this many independent points
  double trans_noise_per_m = 0.10;   ///< odometry translation std per metre, m/m
  double rot_noise_per_rad = 0.15;   ///< odometry rotation std per radian, rad/rad
  double rot_noise_per_m = 0.05;     ///< rotation std per metre, rad/m
  double min_trans_noise_m = 0.002;  ///< per step, keeps the cloud from collapsing, m
  double min_rot_noise_rad = 0.002;  ///< per step, rad
  double alpha_slow = 0.001, alpha_fast = 0.1;  ///< averages that drive random injection
  double max_injection = 0.05;    ///< at most this share of particles injected per frame
  double cluster_radius_m = 0.5;  ///< estimate = mean of particles this close to the best
};

class MonteCarloLocalizer {
 public:
  MonteCarloLocalizer(const FieldModel& field, const DistanceGrid& grid, const MclConfig& config,
                      std::uint32_t seed);

  /// Particles drawn around a start pose (a start hint), std in m and rad.
  void reset(const Pose2& pose, double sigma_m, double sigma_rad);
  /// motion: robot-frame odometry motion since the last call (inverse(prev) * curr).
  void update(const Pose2& motion, const GroundPoints& points);
  Pose2 estimate() const { return estimate_; }

 private:
  struct Particle {
    Pose2 pose;
    double log_weight = 0.0;
  };
  Pose2 randomPose();
  /// Precomputed log-likelihood of a point at a cell (the "likelihood field"), nearest cell.
  double logLikelihoodAt(double x, double y) const;
  void resample(double inject_share);
  /// Weighted mean of the particles within cluster_radius_m of `centre`.
  void computeEstimate(const Pose2& centre);

  const FieldModel& field_;
  const DistanceGrid& grid_;
  MclConfig config_;
  std::mt19937 rng_;
  std::vector<Particle> particles_;
  std::vector<double> weights_;
  std::vector<float> log_field_;  ///< per DistanceGrid node, row-major
  double log_outside_ = 0.0;      ///< log-likelihood beyond the grid (uniform share only)
  double w_slow_ = 0.0, w_fast_ = 0.0;
  Pose2 estimate_;
};

}  // namespace houghloc::bench
