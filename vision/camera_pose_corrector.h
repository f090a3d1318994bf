#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_models/pose3.h"
#include "vision/ground_projection.h"
#include "vision/line_segments.h"

namespace houghloc {

struct CameraPoseCorrectionConfig {
  bool enabled = false;               ///< off by default: see docs/vision.md for when it helps
  double min_segment_length_m = 0.8;  ///< shorter segments give too noisy directions
  double max_segment_rms_m = 0.006;   ///< only clean straight fits constrain the tilt
  double min_point_sigma_m = 0.004;   ///< floor of the per-point noise used for a direction's sigma
  double max_pair_angle_rad = 0.2;    ///< pairs further than this (11 deg) from parallel or
                                      ///< perpendicular are not field-line pairs (arcs, misfits)
  double huber_rad = 0.02;            ///< pair residuals beyond this count linearly (robust)
  double step_sigma_rad = 0.01;       ///< one frame's estimate is pulled toward the previous one
                                      ///< with this sigma (directions it cannot observe stay)
  double max_correction_rad = 0.07;   ///< |roll| and |pitch| corrections are clamped (4 deg)
  double forgetting = 0.995;          ///< share of the accumulated information kept per frame,
                                      ///< so a changing calibration error is followed
  double max_information = 1e7;       ///< cap (1/rad^2): keeps the estimate able to move
  int iterations = 4;                 ///< Gauss-Newton steps per frame
};

/// Online estimate of a roll and pitch error of the recorded camera pose (DESIGN §3 Pose3 angles)
/// from the lines themselves: field lines are pairwise parallel or perpendicular (the centre
/// circle aside), and a wrong camera tilt projects them onto the ground with converging or skewed
/// directions. Each frame adds a Gauss-Newton fit of (droll, dpitch) that makes the projected
/// segment pairs parallel/perpendicular again, fused with the previous estimate by recursive
/// least squares with forgetting. Yaw and height are not observable this way.
class CameraPoseCorrector {
 public:
  explicit CameraPoseCorrector(const CameraPoseCorrectionConfig& config = {}) : config_(config) {}

  /// The recorded pose with the current correction added.
  Pose3 corrected(const Pose3& recorded) const;

  /// Adds one frame's segments (fitted with corrected(recorded)); returns whether the frame
  /// constrained the estimate.
  bool update(const std::vector<GroundSegment>& segments, const Pose3& recorded);

  /// (roll, pitch) correction, rad.
  const Eigen::Vector2d& correction() const { return estimate_; }
  /// Accumulated information (inverse covariance, 1/rad^2).
  const Eigen::Matrix2d& information() const { return information_; }
  void reset();

 private:
  double directionSigma(const GroundSegment& segment) const;

  CameraPoseCorrectionConfig config_;
  Eigen::Vector2d estimate_ = Eigen::Vector2d::Zero();
  Eigen::Matrix2d information_ = Eigen::Matrix2d::Zero();
};

}  // namespace houghloc
