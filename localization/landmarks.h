#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "localization/hough_transform.h"
#include "localization/orientation_search.h"
#include "localization/pose_hypothesis.h"

namespace houghloc {

/// Beyond the paper: the centre circle and the penalty marks as point landmarks.
struct LandmarkConfig {
  double circle_cell_m = 0.05;       ///< cell of the circle-centre vote accumulator
  double circle_band_m = 0.06;       ///< points this close to the circle are its inliers
  double circle_min_support = 10.0;  ///< point weight on the circle
  double circle_min_arc_rad = 0.6;   ///< angular coverage of the inliers around the centre
  /// A straight line stays within circle_band_m of a circle of radius R over an arc of
  /// 2 sqrt(2 band / R) rad (tangent); the inliers must cover this many times that arc too, so
  /// that short arcs of large circles count and lines near small ones do not (unitless).
  double circle_tangent_factor = 1.2;
  /// A landmark fixes the position up to a rotation about it; besides the step-2 headings, the
  /// heading is scanned at this step (rad) scoring all points (the halfway line through the
  /// circle, the lines next to a mark) ...
  double heading_scan_step_rad = 2.0 * M_PI / 180.0;
  int heading_scan_maxima = 4;     ///< ... and this many best local maxima become candidates
  double mark_link_m = 0.05;       ///< extra extent allowed around a mark for noise
  double mark_isolation_m = 0.35;  ///< no other point this close to a mark blob
  int mark_min_points = 3;
  int max_marks = 4;  ///< mark blobs used per frame
};

/// A circle of known radius found in the points (robot frame).
struct CircleObservation {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< m, robot frame
  double support = 0.0;                              ///< inlier point weight
  double arc_rad = 0.0;                              ///< angular coverage of the inliers
};

/// Fits a circle of the map's radius: each point votes for the centres at `radius` around it,
/// the best cell is refined by Gauss-Newton on the radial distances and accepted when its
/// inliers cover enough of the circle (a straight line cannot).
std::optional<CircleObservation> fitCircle(const WeightedPoints& points, double radius_m,
                                           const LandmarkConfig& config);

/// Small isolated blobs of points no larger than a mark of `mark_size_m`: centres, robot frame.
std::vector<Eigen::Vector2d> findMarkBlobs(const WeightedPoints& points, double mark_size_m,
                                           const LandmarkConfig& config);

/// Poses that put the landmark seen at p_robot onto the map landmark at p_field, one per heading
/// candidate: T = p_field - Rz(theta_R) p_robot (the circle centre plus the halfway line fixes the
/// pose up to the field's symmetry; so does a mark plus a line direction).
std::vector<PoseHypothesis> landmarkCandidates(const Eigen::Vector2d& p_robot,
                                               const Eigen::Vector2d& p_field,
                                               const std::vector<OrientationCandidate>& headings,
                                               HypothesisSource source, double support);

}  // namespace houghloc
