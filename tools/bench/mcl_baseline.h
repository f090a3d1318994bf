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
  double point_sigma_m = 0.05;      ///< likelihood field std, m
  double z_random = 0.05;           ///< uniform share of the point likelihood (outliers)
  double likelihood_points = 30.0;  ///< a frame counts as this many independent points
  // Odometry noise as a random walk (variance grows with distance walked and angle turned),
  // the same model and numbers as the tracker's MotionModelConfig and the renderer's odometry
  // errors: 10 cm after 1 m, 0.15 rad after 1 rad. A std proportional to each 1 cm step would
  // be ten times too small after 1 m at 30 fps, and the cloud could not follow foot slips.
  double trans_var_per_m = 0.01;                ///< translation variance per metre walked, m^2/m
  double trans_var_per_rad = 4e-4;              ///< translation variance per radian turned, m^2/rad
  double rot_var_per_rad = 0.0225;              ///< heading variance per radian turned, rad^2/rad
  double rot_var_per_m = 0.0025;                ///< heading variance per metre walked, rad^2/m
  double min_trans_noise_m = 0.002;             ///< per step, keeps the cloud from collapsing, m
  double min_rot_noise_rad = 0.002;             ///< per step, rad
  double alpha_slow = 0.001, alpha_fast = 0.1;  ///< averages that drive random injection
  double max_injection = 0.05;  ///< at most this share of particles injected per frame
  /// The estimate is the weighted mean of the particles within cluster_radius_m and
  /// cluster_heading_rad of a centre; the centre is the one of the cluster_candidates best
  /// particles whose cluster holds the most weight (a lone injected particle can be the best one).
  double cluster_radius_m = 0.5;
  double cluster_heading_rad = 0.5;
  int cluster_candidates = 10;
};

class MonteCarloLocalizer {
 public:
  MonteCarloLocalizer(const FieldModel& field, const DistanceGrid& grid, const MclConfig& config,
                      std::uint32_t seed);

  /// Particles drawn around a start pose (a start hint), std in m and rad.
  void reset(const Pose2& pose, double sigma_m, double sigma_rad);
  /// Particles uniform over the field (no start hint).
  void resetUniform();
  /// motion: robot-frame odometry motion since the last call (inverse(prev) * curr).
  void update(const Pose2& motion, const GroundPoints& points);
  Pose2 estimate() const { return estimate_; }
  /// Weighted covariance (x, y, theta) of the particles around the estimate (cluster only).
  const Eigen::Matrix3d& covariance() const { return covariance_; }

 private:
  struct Particle {
    Pose2 pose;
    double log_weight = 0.0;
  };
  Pose2 randomPose();
  /// Precomputed log-likelihood of a point at a cell (the "likelihood field"), nearest cell.
  double logLikelihoodAt(double x, double y) const;
  void resample(double inject_share);
  bool inCluster(const Pose2& p, const Pose2& centre) const;
  /// Centre of the heaviest cluster (see MclConfig::cluster_candidates).
  Pose2 heaviestClusterCentre() const;
  /// Weighted mean and covariance of the particles in the cluster around `centre`.
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
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Identity();
};

}  // namespace houghloc::bench
