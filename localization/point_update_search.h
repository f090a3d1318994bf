#pragma once

#include <vector>

#include "field_models/ground_points.h"
#include "localization/feature_index.h"
#include "localization/gaussian_pose.h"
#include "localization/point_update.h"

namespace houghloc {

/// The start of the point update's iterations: the prior mean, or, when the prior is wide along
/// one position axis (largest std above config.search_min_sigma_m), the pose along that axis
/// that best explains the points (prior chi^2 + capped point log-likelihood; see
/// PointUpdateConfig). Returns the prior mean when nothing scores better.
Pose2 searchUpdateStart(const GaussianPose& prior, const std::vector<GroundPoint>& points,
                        const FeatureIndex& index, const PointUpdateConfig& config);

}  // namespace houghloc
