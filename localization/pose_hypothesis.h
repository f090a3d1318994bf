#pragma once

#include <Eigen/Core>

#include "field_models/pose2.h"

namespace houghloc {

/// What a hypothesis pins down (paper step 4: M >= 2, M = 1 and M = 0 directions).
enum class HypothesisKind {
  kFull,         ///< lines in two directions, circle or mark: x, y and theta
  kParallel,     ///< only parallel lines: 1-D Gaussian, large variance along the lines
  kHeadingOnly,  ///< heading only, position unknown
};

/// Where a candidate came from (diagnostics).
enum class HypothesisSource { kLines, kCircle, kMark };

/// A Gaussian pose hypothesis (paper eq. 1): mean field_T_robot, 3x3 covariance over
/// (x [m], y [m], theta [rad]), and weight (normalised over the returned set).
struct PoseHypothesis {
  Pose2 field_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
  double weight = 0.0;

  HypothesisKind kind = HypothesisKind::kFull;
  HypothesisSource source = HypothesisSource::kLines;
  /// Unit field-frame direction along the lines of a kParallel hypothesis.
  Eigen::Vector2d line_direction = Eigen::Vector2d::Zero();
  double support = 0.0;       ///< Hough support of the candidate (point weight on map lines)
  double score = 0.0;         ///< robust positive score minus negative evidence (point weight)
  double penalty = 0.0;       ///< negative evidence included in `score` (point weight)
  double inlier_share = 0.0;  ///< share of point weight within the inlier distance of a line
  double rms_m = 0.0;         ///< RMS point-to-line distance of the inliers after refinement
};

}  // namespace houghloc
