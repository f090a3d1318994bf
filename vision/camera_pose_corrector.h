#pragma once

#include <Eigen/Core>
#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose2.h"
#include "field_models/pose3.h"
#include "vision/ground_projection.h"
#include "vision/line_segments.h"
#include "vision/map_tilt_observation.h"

namespace houghloc {

struct CameraPoseCorrectionConfig {
  bool enabled = true;                  ///< harmless on exact extrinsics (significance gate below)
  double min_segment_length_m = 0.5;    ///< shorter segments give too noisy directions, and a
                                        ///< 0.5 m chord of the 0.75 m centre circle bends 4 cm,
                                        ///< so no circle piece passes the rms limit
  double max_segment_rms_m = 0.006;     ///< only clean straight fits constrain the tilt
  int min_segment_points = 8;           ///< fewer spots give no trustworthy rms (a 4-spot far
                                        ///< segment 2.5 deg off once moved the estimate 0.5 deg)
  double min_point_sigma_m = 0.004;     ///< floor of the per-point noise used for a direction's
                                        ///< sigma, at the camera; grows as (1 + (range / 2 m)^2),
                                        ///< like a pixel's ground footprint
  int max_segments_per_frame = 12;      ///< the longest ones are kept (bounds the solver's cost)
  int window_frames = 600;              ///< frames whose segments are kept (20 s at 30 Hz): the
                                        ///< error is a constant bias, so old frames still count,
                                        ///< and a walk needs seconds to show enough geometry (a
                                        ///< changed error is followed within this many frames)
  double max_residual_rad = 0.35;       ///< segments further than this (20 deg) from their frame's
                                        ///< two field directions are no straight field lines
  double huber_sigmas = 3.0;            ///< residuals beyond this many sigmas count linearly
  double prior_sigma_rad = 0.05;        ///< weak pull toward no correction (3 deg), for directions
                                        ///< the lines seen so far do not constrain
  double max_correction_rad = 0.07;     ///< larger |roll| or |pitch| estimates (4 deg) are
                                        ///< runaways on too little data: not applied
  int runaway_restart_frames = 60;      ///< a runaway restarts from 0 at every frame while the
                                        ///< window holds at most this many frames (cheap then)
  int runaway_restart_solves = 300;     ///< then every this many frames (10 s at 30 Hz): a wrong
                                        ///< minimum is left in time, and the full
                                        ///< re-linearisation of a restart stays rare
  int iterations = 8;                   ///< Gauss-Newton steps per frame (on the linearised
                                        ///< residuals: cheap)
  double relinearize_rad = 3e-4;        ///< a frame's residuals are re-linearised once the
                                        ///< estimate moved this far from where they were (the
                                        ///< tilt's effect is smooth; keeps the cost per frame low)
  int min_frames = 3;                   ///< frames with >= 2 segments needed before correcting
  bool use_circles = true;              ///< centre-circle arcs must fit a circle of the map's
                                        ///< radius: a strong pitch (scale) and roll (skew) cue
  double circle_radius_m = 0.0;         ///< set by VisionPipeline from the segments' circle radius
                                        ///< (the map); 0 = arcs unused
  double max_circle_residual_m = 0.05;  ///< arc points further off the fitted circle are gated
  double significance_sigmas = 4.0;     ///< a roll or pitch estimate is applied only when it is
                                        ///< this many of its standard deviations (from the fit's
                                        ///< information, scaled by the residual chi^2 when that
                                        ///< exceeds 1) away from 0: with an exact calibration the
                                        ///< line geometry of a few frames must not move the pose
  double min_correction_rad = 3e-4;     ///< smaller estimates are not applied however certain
                                        ///< (0.017 deg moves a point at 3 m by 3 mm): points
                                        ///< matched to the map resolve the tilt to a few
                                        ///< thousandths of a degree, finer than the line spots'
                                        ///< own sub-millimetre biases
  MapTiltConfig map;                    ///< points matched to the map, in frames that come with
                                        ///< a field pose (the localizer's)
  bool shared_between_cameras = false;  ///< the tools give a recording's cameras one corrector
                                        ///< (VisionPipeline::sharePoseCorrection): right when
                                        ///< their recorded poses share one roll/pitch error (a
                                        ///< NAO's head pitch joint), wrong for separate mount
                                        ///< errors; lets a NAO's bottom camera, whose own view
                                        ///< never shows its tilt, use the top camera's lines
};

/// What one frame adds to the corrector besides its segments and arcs: the line spots' rays
/// and, when the localizer tracks the robot, its field pose for this frame.
struct CorrectorMapInput {
  const std::vector<SpotRay>* rays = nullptr;  ///< camera frame
  std::optional<Pose2> field_T_robot;          ///< none: the frame adds no map residuals
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
/// Frames that come with the localizer's field pose (and a map, setFieldModel) add their line
/// points' distances to the map lines (MapTiltObservation), each frame's field pose eliminated
/// like its heading; points are matched only out to the range where the tilt, as well as the
/// lines and arcs alone determine it, moves them by less than half the match gate.
class CameraPoseCorrector {
 public:
  explicit CameraPoseCorrector(const CameraPoseCorrectionConfig& config = {}) : config_(config) {}

  /// The recorded pose with the current correction added.
  Pose3 corrected(const Pose3& recorded) const;

  /// Adds one frame's segments and centre-circle arcs (their rays are in the camera frame, so
  /// any pose they were fitted with is fine) and re-solves; returns whether the window
  /// constrained the estimate.
  bool update(const std::vector<GroundSegment>& segments,
              const std::vector<CircleCandidate>& circles, const Pose3& recorded,
              const CorrectorMapInput& map = {});
  bool update(const std::vector<GroundSegment>& segments, const Pose3& recorded) {
    return update(segments, {}, recorded);
  }

  /// The field map that frames with a field pose are matched against (none: map residuals off).
  void setFieldModel(std::shared_ptr<const FieldModel> field) { field_ = std::move(field); }

  /// Points of the last frame matched to the map (0: none, or its field pose was not trusted).
  int lastMapInliers() const { return last_map_inliers_; }
  /// (roll, pitch) correction applied by corrected(), rad.
  const Eigen::Vector2d& correction() const { return applied_; }
  /// The estimate before the min_frames / significance gates (the last solve's solution
  /// clamped to max_correction_rad), rad.
  Eigen::Vector2d estimate() const {
    return solution_.cwiseMax(-config_.max_correction_rad).cwiseMin(config_.max_correction_rad);
  }
  /// Standard deviation of estimate() (roll, pitch), rad; infinite before the first solve.
  const Eigen::Vector2d& estimateSigma() const { return sigma_; }
  void reset();

 private:
  struct Observation {
    Eigen::Vector3d ray_a, ray_b;  ///< camera frame
    double sigma_rad = 0.0;        ///< direction sigma on the ground
  };
  struct ArcObservation {
    std::vector<Eigen::Vector3d> rays;  ///< camera frame
    double sigma_m = 0.0;               ///< point noise on the ground
  };
  struct Frame {
    Pose3 recorded;
    std::vector<Observation> observations;
    std::vector<ArcObservation> arcs;
    std::vector<MapTiltObservation> map;  ///< none or one
    double map_range_m = 0.0;             ///< map points matched out to here (mapRange)
    long line_residuals = 0;              ///< the first ones: segments and arcs, not the map
    /// Whitened residuals r (NaN: unusable) and their Jacobian at correction `at`; gates in
    /// sigmas. The solver uses r + J (c - at).
    Eigen::Vector2d at = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
    Eigen::VectorXd r, gate;
    Eigen::Matrix<double, Eigen::Dynamic, 2> jacobian;
    /// When every residual stays unusable, or inside both its gate and the Huber threshold,
    /// for any c within relinearize_rad of `at`, the frame's part of the normal equations is
    /// the same quadratic there: sums kept once instead of a loop over residuals per iteration.
    bool quadratic = false;
    Eigen::Matrix2d jtj = Eigen::Matrix2d::Zero(), line_jtj = Eigen::Matrix2d::Zero();
    Eigen::Vector2d jtr = Eigen::Vector2d::Zero();
    double rtr = 0.0;
    long used = 0;
  };

  /// Ground noise of a line point at range_m: the floor min_point_sigma_m grows as
  /// (1 + (range / 2 m)^2), like a pixel's footprint on the ground.
  double pointSigma(double range_m) const;
  double directionSigma(const GroundSegment& segment) const;
  /// Whitened residuals of one frame's observations for correction c (NaN when unusable) and,
  /// when given, each one's gate in sigmas.
  void frameResiduals(const Frame& frame, const Eigen::Vector2d& c, std::vector<double>* out,
                      std::vector<double>* gates) const;
  /// Appends the raw residuals (m, NaN when unusable) of one arc's points to its fixed-radius
  /// circle under `pose`.
  void arcResiduals(const ArcObservation& arc, const Pose3& pose, std::vector<double>* out) const;
  /// How far out a frame's points can be matched to the map with the tilt as well known as the
  /// lines and arcs alone make it (line_sigma_), m.
  double mapRange(const Frame& frame) const;
  void linearize(Frame* frame, const Eigen::Vector2d& c) const;
  /// Sets the frame's kept sums (Frame::quadratic) after linearize().
  void cacheQuadratic(Frame* frame) const;
  /// IRLS Gauss-Newton on the linearised frames from solution_; false on a numerical breakdown.
  bool solve();

  /// The frame's map observation from the spots within range (every k-th of them).
  std::optional<MapTiltObservation> mapObservation(const CorrectorMapInput& input,
                                                   const Pose3& recorded) const;

  CameraPoseCorrectionConfig config_;
  std::shared_ptr<const FieldModel> field_;
  std::deque<Frame> frames_;
  int last_map_inliers_ = 0;
  /// Solves in a row that ended at or beyond max_correction_rad (a runaway, not applied).
  int runaway_frames_ = 0;
  bool runaway() const { return runaway_frames_ > 0; }
  Eigen::Vector2d solution_ = Eigen::Vector2d::Zero();  ///< the last solve's, before clamping
  Eigen::Vector2d applied_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d sigma_ = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  /// The estimate's sigma from the lines and arcs alone (the map residuals left out).
  Eigen::Vector2d line_sigma_ = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
};

}  // namespace houghloc
