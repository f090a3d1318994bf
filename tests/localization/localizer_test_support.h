#pragma once

#include <vector>

#include "field_models/field_model.h"
#include "localization/localizer.h"
#include "tests/localization/tracking_scenario.h"

namespace houghloc::testing {

/// DESIGN §5.3: within 0.10 m and 3 deg.
bool correctPose(const Pose2& estimate, const Pose2& truth);
/// Correct, or correct for the field's point mirror (the symmetry no single frame resolves).
bool correctUpToSymmetry(const Pose2& estimate, const Pose2& truth);
/// The best hypothesis is correct up to symmetry.
bool estimateCorrect(const LocalizationEstimate& estimate, const Pose2& truth);

/// Ground truth check of a frame (independent of the localizer): at least `min_points` points
/// within 5 cm of lines along x and as many along y (the centre circle counts for both).
bool seesTwoDirections(const FieldModel& field, const Pose2& field_T_robot,
                       const GroundPoints& points, int min_points = 15);

/// Every number of the estimate is finite, the weights are in [0, 1] and sum to one.
bool estimateFinite(const LocalizationEstimate& estimate);

/// Exact equality of two estimates (status, ids, ages, means, covariances, weights).
bool sameEstimate(const LocalizationEstimate& a, const LocalizationEstimate& b);

/// A hint of `kind` with `poses` (DESIGN §7).
LocalizationHint hint(HintKind kind, std::vector<GaussianPose> poses = {});

/// A Gaussian pose at `mean` with independent standard deviations: position sigma_m (m) in x and
/// y, heading sigma_rad (rad).
GaussianPose gaussianAt(const Pose2& mean, double weight = 1.0, double sigma_m = 0.1,
                        double sigma_rad = 0.055);

/// A walk like the tracking accuracy tests': figure eight scaled to the field, camera range
/// scaled with the field's size.
ScenarioConfig walkOn(const FieldModel& field, int frames, std::uint32_t seed);

/// The camera pose of a standing NAO's top camera (about 0.5 m high, looking 0.2 rad down).
Pose3 uprightCamera();

}  // namespace houghloc::testing
