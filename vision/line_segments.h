#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_models/pose3.h"
#include "vision/ground_projection.h"

namespace houghloc {

struct LineSegmentConfig {
  bool enabled = true;
  double link_slope = 1.8;                ///< max image slope between linked spots (across / along)
  double link_gap_px = 40.0;              ///< max gap along the scan axis between linked spots
  double link_tolerance_px = 3.0;         ///< allowed deviation from the chain's predicted position
  double split_distance_m = 0.03;         ///< a chain splits where it leaves its chord by more
  double min_length_m = 0.25;             ///< shorter segments are dropped
  int min_points = 4;                     ///< segments and circles need at least this many points
  double max_rms_m = 0.02;                ///< line-fit residual limit
  double circle_radius_m = 0.75;          ///< centre-circle radius (set from the map); 0 = none
  double max_arc_radius_m = 3.0;          ///< bent chains a circle this small fits are arcs
  double circle_radius_tolerance = 0.25;  ///< relative radius deviation accepted: a camera
                                          ///< pitched 2.7 deg off puts the circle 15-25 % off
                                          ///< its radius, and the pitch/roll corrector needs
                                          ///< the arcs most then (it fits them to the exact
                                          ///< radius itself; physar_nao_top)
  double circle_max_rms_m = 0.03;         ///< circle-fit residual limit
  int max_circle_rays = 24;               ///< rays kept per circle candidate (pose correction)
};

/// A straight piece of field line on the ground (robot frame), fitted to linked spots.
struct GroundSegment {
  Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero();  ///< m
  double rms_m = 0.0;
  int num_points = 0;
  /// Camera-frame rays of the first and last spot, so the segment can be re-projected with a
  /// corrected camera orientation (CameraPoseCorrector).
  Eigen::Vector3d ray_a_camera = Eigen::Vector3d::UnitX(), ray_b_camera = Eigen::Vector3d::UnitX();

  double length() const { return (b - a).norm(); }
};

/// A piece of arc whose circle fit matches the centre-circle radius: a centre candidate.
struct CircleCandidate {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< robot frame, m
  double radius_m = 0.0;
  double rms_m = 0.0;
  int num_points = 0;
  /// Camera-frame rays of up to max_circle_rays of its spots, evenly along the arc, so the
  /// arc can be re-projected with a corrected camera tilt (CameraPoseCorrector).
  std::vector<Eigen::Vector3d> rays_camera;
};

struct LineFeatures {
  std::vector<GroundSegment> segments;
  std::vector<CircleCandidate> circles;
};

/// Links spots of neighbouring scanlines into image chains (separately per scan direction),
/// projects each chain with robot_T_camera and splits it into straight ground segments
/// (split-and-merge); chains that bend like the centre circle become circle candidates.
LineFeatures fitLineFeatures(const std::vector<SpotRay>& rays, const Pose3& robot_T_camera,
                             const GroundProjectionConfig& projection,
                             const LineSegmentConfig& config);

}  // namespace houghloc
