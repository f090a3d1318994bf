#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/ground_points.h"
#include "field_models/pose2.h"
#include "localization/localizer.h"
#include "tools/synthetic/synthetic_ground_points.h"

namespace houghloc::testing {

/// Where a hint-matrix walk starts (the places a robot is put by hand).
enum class StartPlace { kCentre, kPenaltyMark, kCorner };
const char* startPlaceName(StartPlace place);

/// A short walk for the placement-hint matrix (docs/tracking.md "Hint matrix"): the robot starts
/// at a random pose of `start`, walks at walk_speed toward the field centre with a weave,
/// panning its head; the points come from tools/synthetic (view, noise, outliers, visible region,
/// field edge). Odometry has relative noise and slip; an optional unannounced kidnap carries the
/// robot to a random pose in the other half (odometry does not see it).
struct HintWalkConfig {
  int frames = 105;
  double fps = 30.0;
  StartPlace start = StartPlace::kCentre;
  std::string view = "nao-top";  ///< tools/synthetic view model
  double walk_speed_m_per_s = 0.2;
  double head_pan_rad = 0.8;  ///< amplitude of the head pan (period head_period_s)
  double head_period_s = 4.0;
  double odometry_noise = 0.10;  ///< per-step relative std of translation and rotation
  double odometry_slip = 0.05;   ///< systematic under-reading of translation
  int kidnap_frame = -1;         ///< negative: none
  std::uint32_t seed = 1;
};

struct HintWalkFrame {
  std::int64_t t_us = 0;
  Pose2 field_T_robot;  ///< ground truth
  Pose2 odometry;       ///< cumulative, noisy
  GroundPoints points;
};

std::vector<HintWalkFrame> makeHintWalk(const FieldModel& field, const HintWalkConfig& config);

/// A RESET_TO hint `offset_m` and `offset_rad` off `truth` (direction and sign drawn from
/// `seed`), position std sigma_m, heading std sigma_rad.
LocalizationHint placementHint(const Pose2& truth, double offset_m, double offset_rad,
                               double sigma_m, double sigma_rad, std::uint32_t seed);

/// What a hint-matrix cell asserts, accumulated over the frames from the hint on (up to the
/// kidnap, if any): a correct pose (DESIGN §5.3) within 1 s of the hint, no flipped frame from
/// then on and, without a kidnap, the twin's weight below 0.05 from the hint on.
struct HintCellResult {
  std::int64_t hint_t_us = 0;
  std::int64_t first_correct_t_us = -1;  ///< -1: never
  int frames = 0;
  int flips = 0;  ///< from the first correct frame on
  double twin_max = 0.0;
  void add(const LocalizationEstimate& estimate, const Pose2& truth);
  bool correctInTime() const {
    return first_correct_t_us >= 0 && first_correct_t_us - hint_t_us <= 1000000;
  }
  bool passes(bool kidnap) const {
    return correctInTime() && flips == 0 && (kidnap || twin_max < 0.05);
  }
  std::string describe() const;
};

/// The best pose is the mirror twin of the truth (closer to it than to the truth, and more than
/// 0.5 m from the truth: the definition of metrics.json `flips`).
bool isFlipped(const Pose2& best, const Pose2& truth);

}  // namespace houghloc::testing
