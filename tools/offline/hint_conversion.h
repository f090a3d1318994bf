#pragma once

#include <vector>

#include "localization/localization_hint.h"
#include "tools/recording/recording.h"

namespace houghloc {

/// hints.csv rows (DESIGN §5.1) as the Localizer's hints (§7): one pose with covariance
/// diag(sigma_x^2, sigma_y^2, sigma_theta^2) for RESET_TO and ADD (sigmas below a floor of
/// 1 cm / 0.5 deg are raised to it: a zero variance would make the tracker's covariance singular).
/// Throws RecordingError naming hints.csv and the hint's time when RESET_TO or ADD has no pose.
std::vector<LocalizationHint> convertHints(const Recording& recording);

}  // namespace houghloc
