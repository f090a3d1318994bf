#pragma once

#include <Eigen/Core>
#include <deque>
#include <vector>

#include "field_models/pose3.h"
#include "vision/ground_projection.h"
#include "vision/line_segments.h"

namespace houghloc {

struct CameraPoseCorrectionConfig {
  bool enabled = false;               ///< off by default: on one exact-extrinsics recording it
                                      ///< still estimated a wrong 0.4 deg pitch (docs/vision.md)
  double min_segment_length_m = 0.3;  ///< shorter segments give too noisy directions
  double max_segment_rms_m = 0.006;   ///< only clean straight fits constrain the tilt
  double min_point_sigma_m = 0.004;   ///< floor of the per-point noise used for a direction's sigma
  int max_segments_per_frame = 12;    ///< the longest ones are kept (bounds the solver's cost)
  int window_frames = 60;             ///< frames whose segments are kept: the error is a constant
                                      ///< bias, so old frames still count (and a changed one is
                                      ///< followed within this many frames)
  double max_residual_rad = 0.35;     ///< segments further than this (20 deg) from their frame's
                                      ///< two field directions are no straight field lines
  double huber_sigmas = 3.0;          ///< residuals beyond this many sigmas count linearly
  double prior_sigma_rad = 0.05;      ///< weak pull toward no correction (3 deg), for directions
                                      ///< the lines seen so far do not constrain
  double max_correction_rad = 0.07;   ///< |roll| and |pitch| corrections are clamped (4 deg)
  int iterations = 4;                 ///< Gauss-Newton steps per frame
  int min_frames = 3;                 ///< frames with >= 2 segments needed before correcting
  double min_applied_rad = 0.0044;    ///< a roll or pitch estimate below this (0.25 deg) is not
                                      ///< applied: the line geometry of a few frames determines
                                      ///< the tilt only to about 0.1 deg, and with an exact
                                      ///< calibration applying such noise would cost accuracy
};

/// Online estimate of a roll and pitch error of the recorded camera pose (DESIGN §3 Pose3 angles)
/// from the lines themselves: every straight field line runs along one of two perpendicular
/// field directions, and a wrong camera tilt projects them onto the ground converging (pitch:
/// the vanishing point of parallel lines is off the horizon) or skewed (roll). The corrector keeps
/// the segments of the last window_frames frames as camera-frame rays and solves, each frame, for
/// the (droll, dpitch) under which every frame's segments are closest to parallel/perpendicular:
/// each frame's own field direction (the robot's heading modulo 90 deg) is eliminated in closed
/// form (weighted circular mean of 4 x direction), residuals are Huber-weighted in units of each
/// segment's direction sigma. Yaw and height errors are not observable this way.
class CameraPoseCorrector {
 public:
  explicit CameraPoseCorrector(const CameraPoseCorrectionConfig& config = {}) : config_(config) {}

  /// The recorded pose with the current correction added.
  Pose3 corrected(const Pose3& recorded) const;

  /// Adds one frame's segments (their rays are in the camera frame, so any pose they were fitted
  /// with is fine) and re-solves; returns whether the window constrained the estimate.
  bool update(const std::vector<GroundSegment>& segments, const Pose3& recorded);

  /// (roll, pitch) correction applied by corrected(), rad.
  const Eigen::Vector2d& correction() const { return applied_; }
  /// The estimate before the min_frames / min_applied_rad gates, rad.
  const Eigen::Vector2d& estimate() const { return estimate_; }
  void reset();

 private:
  struct Observation {
    Eigen::Vector3d ray_a, ray_b;  ///< camera frame
    double sigma_rad = 0.0;        ///< direction sigma on the ground
  };
  struct Frame {
    Pose3 recorded;
    std::vector<Observation> observations;
  };

  double directionSigma(const GroundSegment& segment) const;
  /// Whitened, Huber-weighted residuals of every observation for correction c (zero for gated
  /// ones); `weights` (IRLS, from the residuals at c) are used when given, else computed.
  Eigen::VectorXd residuals(const Eigen::Vector2d& c, std::vector<double>* weights) const;

  CameraPoseCorrectionConfig config_;
  std::deque<Frame> frames_;
  Eigen::Vector2d estimate_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d applied_ = Eigen::Vector2d::Zero();
};

}  // namespace houghloc
