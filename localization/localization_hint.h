#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "localization/gaussian_pose.h"

namespace houghloc {

/// What the behaviour stack or the game controller tells localization (DESIGN §7,
/// localization_hint_t; hints.csv in §5.1).
enum class HintKind {
  kUnknown,  ///< the pose is unknown: forget every hypothesis and relocalise globally
  kResetTo,  ///< replace all hypotheses by `poses` (initial positions, penalty re-entry)
  kAdd,      ///< add `poses` to the hypotheses
  kOwnHalf,  ///< the robot is in its own half (x <= 0): hypotheses in the other half are mirrored
  kMirror,   ///< the estimate is flipped: replace each hypothesis by its mirror
};

struct LocalizationHint {
  HintKind kind = HintKind::kUnknown;
  std::int64_t t_us = 0;
  std::vector<GaussianPose> poses;  ///< field_T_robot with covariance, for kResetTo and kAdd
};

/// "UNKNOWN", "RESET_TO", "ADD", "OWN_HALF", "MIRROR" (the names of DESIGN §5.1 and §7).
const char* hintKindName(HintKind kind);
/// Inverse of hintKindName(); empty for an unknown name.
std::optional<HintKind> parseHintKind(const std::string& name);

}  // namespace houghloc
