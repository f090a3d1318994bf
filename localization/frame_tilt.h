#pragma once

#include <vector>

#include "field_models/ground_points.h"
#include "localization/feature_index.h"
#include "localization/gaussian_pose.h"
#include "localization/point_update.h"

namespace houghloc {

/// The point update of every hypothesis for one frame, with one camera tilt for the frame.
/// A camera pitched or rolled off its recorded pose is the camera's error, not a hypothesis's:
/// fitted per hypothesis (updateWithGroundPoints), a wrong place that a couple of degrees of
/// tilt make fit a few points would outweigh the place that fits them untilted. So each
/// hypothesis first fits its own tilt where the recorded pose explains it poorly; the fit with
/// the highest posterior (log prior weight + likelihood_points x mean per-point log-likelihood
/// + the tilt's Gaussian log prior, PointUpdateConfig::pitch_sigma_rad / roll_sigma_rad) sets
/// the frame's tilt, and every hypothesis fitted at another tilt is fitted again at that one.
/// Without tilt sigmas this is updateWithGroundPoints per hypothesis. Results are in the
/// order of `priors`.
std::vector<PointUpdateResult> updateWithOneFrameTilt(const std::vector<GaussianPose>& priors,
                                                      const std::vector<GroundPoint>& points,
                                                      const FeatureIndex& index,
                                                      const PointUpdateConfig& config,
                                                      double likelihood_points);

/// The points as a camera whose (roll, pitch) is `tilt` (rad) off its recorded pose sees them:
/// each moved by its GroundPoint::tilt_jacobian (first order; not where it is not finite).
std::vector<GroundPoint> pointsWithTilt(const std::vector<GroundPoint>& points,
                                        const Eigen::Vector2d& tilt);

}  // namespace houghloc
