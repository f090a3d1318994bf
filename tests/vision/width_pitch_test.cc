#include "vision/width_pitch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "vision/camera_presets.h"

namespace houghloc {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kLineWidth = 0.05;

/// Runs as the vision records them when it rejects candidates as too wide: the width a line has
/// in the image of `truth` (the camera's real pose), the width `recorded` (the pose the vision
/// was given) expects, at pixels on a grid below both horizons.
std::vector<LineSpot> runsOfLines(const CameraModel& recorded, const CameraModel& truth) {
  std::vector<LineSpot> runs;
  for (int v = 20; v < recorded.height(); v += 23) {
    for (int u = 30; u < recorded.width(); u += 61) {
      const auto seen = truth.expectedLineWidthPx(u, v, kLineWidth);
      const auto expected = recorded.expectedLineWidthPx(u, v, kLineWidth);
      if (!seen || !expected) continue;
      const bool vertical = (u + v) % 2 == 0;
      runs.push_back({Eigen::Vector2f(u, v), static_cast<float>(vertical ? seen->y() : seen->x()),
                      static_cast<float>(vertical ? expected->y() : expected->x()), vertical});
    }
  }
  return runs;
}

TEST(WidthPitch, FindsThePitchTheWidthsAskFor) {
  const CameraPreset preset = cameraPreset("nao-top");
  const CameraModel recorded(preset.intrinsics, preset.robot_T_camera);
  for (const double error_deg : {-15.0, -6.0, 8.0}) {
    Pose3 real = preset.robot_T_camera;
    real.pitch += error_deg * kDeg;
    const CameraModel truth(preset.intrinsics, real);
    const std::vector<LineSpot> runs = runsOfLines(recorded, truth);
    ASSERT_GE(runs.size(), 20u) << error_deg;
    const std::optional<double> offset =
        fitPitchToWidths(recorded, runs, LineSpotConfig{}, WidthPitchConfig{});
    ASSERT_TRUE(offset.has_value()) << error_deg;
    // The width tests accept 0.4-1.7x the expected width, so several offsets pass every run; the
    // one kept lies within a few degrees of the error.
    EXPECT_NEAR(*offset / kDeg, error_deg, 4.0) << error_deg;
  }
}

TEST(WidthPitch, AboveABoundTheWidthsGiveThePitchWithinTheRange) {
  // A pose whose pitch is a lower bound (field_top_pitch.h): the spots' widths place the pitch in
  // [bound, bound + range], at its end when the real pitch lies beyond it.
  const CameraPreset preset = cameraPreset("nao-top");
  const CameraModel bound(preset.intrinsics, preset.robot_T_camera);
  const double range = 0.115;
  for (const double error_deg : {0.0, 3.0, 5.0, 10.0}) {
    Pose3 real = preset.robot_T_camera;
    real.pitch += error_deg * kDeg;
    std::vector<LineSpot> spots = runsOfLines(bound, CameraModel(preset.intrinsics, real));
    // Accepted spots are at least a pixel wide (thinner far lines give no candidate).
    spots.erase(std::remove_if(spots.begin(), spots.end(),
                               [](const LineSpot& spot) { return spot.width_px < 1.f; }),
                spots.end());
    const double offset = fitPitchAboveBound(bound, spots, range, WidthPitchConfig{});
    EXPECT_NEAR(offset, std::min(error_deg * kDeg, range), 0.6 * kDeg) << error_deg;
  }
  EXPECT_EQ(fitPitchAboveBound(bound, {}, range, WidthPitchConfig{}), 0.0);
}

TEST(WidthPitch, NoOffsetForWidthsNoPitchExplains) {
  const CameraPreset preset = cameraPreset("nao-top");
  const CameraModel recorded(preset.intrinsics, preset.robot_T_camera);
  std::vector<LineSpot> runs = runsOfLines(recorded, recorded);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> factor(3.0f, 40.0f);
  // Each run too wide by its own random factor (robots, feet, a ball): no one pitch fits most.
  for (LineSpot& run : runs) run.width_px = run.expected_px * factor(random) + 3.0f;
  EXPECT_FALSE(fitPitchToWidths(recorded, runs, LineSpotConfig{}, WidthPitchConfig{}));
  // Too few runs, or the fit switched off.
  const std::vector<LineSpot> few(runs.begin(), runs.begin() + 3);
  EXPECT_FALSE(fitPitchToWidths(recorded, few, LineSpotConfig{}, WidthPitchConfig{}));
  WidthPitchConfig off;
  off.enabled = false;
  Pose3 real = preset.robot_T_camera;
  real.pitch -= 10 * kDeg;
  const std::vector<LineSpot> pitched = runsOfLines(recorded, CameraModel(preset.intrinsics, real));
  EXPECT_FALSE(fitPitchToWidths(recorded, pitched, LineSpotConfig{}, off));
  // A config typo (a step of 1e-12 rad, offsets up to 1e9 rad) returns at once, with an offset
  // within a quarter turn.
  WidthPitchConfig typo;
  typo.step_rad = 1e-12;
  typo.max_offset_rad = 1e9;
  const std::optional<double> any = fitPitchToWidths(recorded, pitched, LineSpotConfig{}, typo);
  if (any) {
    EXPECT_LE(std::abs(*any), M_PI / 2);
  }
}

}  // namespace
}  // namespace houghloc
