// Bright light leaves a line on bright turf less rise than the turf's noise asks for: the
// sensor stops at 255. A run whose peak saturates is asked at most a share of the rise left
// (LineSpotConfig::headroom_share, SpotThresholds), but never less than the turf's own texture
// allows for (headroom_min_textures). What keeps bright turf itself out is asserted on real
// frames (RealFramesTest.FramesShowingNoLineGiveFewPoints: sunlit turf near saturation on
// physar_nao_bottom gives points without the texture's floor and the saturated peak).
#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/core.hpp>
#include <vector>

#include "vision/spot_thresholds.h"
#include "vision_test_views.h"

namespace houghloc {
namespace {

/// The light grows from the left image border to the right one (a low sun from the side): the
/// turf's luma spreads over the view more than its texture does, without forming two light
/// levels (FieldColorConfig::min_light_ratio), and the paint saturates on the right.
constexpr double kLeftGain = 1.0;
constexpr double kRightGain = 2.0;
/// The turf's texture at gain 1 (grey levels); light scales it.
constexpr double kSideLightTexture = 12;

/// The image in the light above: (pixel + texture) x gain of its column, saturated at 255.
cv::Mat inSideLight(const cv::Mat& image, double left_gain, double right_gain) {
  const cv::Mat noise = testing::turfTexture(image.size(), 5) * kSideLightTexture;
  cv::Mat out, noise3;
  image.convertTo(out, CV_32FC3);
  cv::merge(std::vector<cv::Mat>{noise, noise, noise}, noise3);
  out += noise3;
  for (int u = 0; u < out.cols; ++u) {
    out.col(u) *= left_gain + (right_gain - left_gain) * u / (out.cols - 1.0);
  }
  out.convertTo(out, CV_8UC3);
  return out;
}

struct SideLightRun {
  testing::PointScore score;
  size_t bright = 0;  ///< points in the brightest third of the image (columns)
};

SideLightRun runWithHeadroom(const testing::TestView& view, const cv::Mat& image,
                             double headroom_share) {
  VisionConfig config;
  config.spots.headroom_share = headroom_share;
  const testing::VisionRun run = testing::runVision(view, image, config);
  SideLightRun found;
  found.score = run.score;
  for (const GroundPoint& p : run.points) found.bright += p.pixel.x() >= 2.0 * image.cols / 3.0;
  return found;
}

TEST(SaturatedLight, LinesOnBrightTurfKeepTheirPoints) {
  testing::SyntheticStyle style;
  style.noise_sigma = 1.0;
  const testing::TestView& view =
      testing::testView("nao-top", "spl", Pose2(-2.0, -1.0, 0.5), style);
  const cv::Mat image = inSideLight(view.image, kLeftGain, kRightGain);
  const SideLightRun uncapped = runWithHeadroom(view, image, 0.0),
                     capped = runWithHeadroom(view, image, LineSpotConfig().headroom_share);
  std::printf(
      "no headroom cap: %zu points (%zu in the bright third), capped: %zu (%zu), precision %.3f "
      "/ %.3f\n",
      uncapped.score.points, uncapped.bright, capped.score.points, capped.bright,
      uncapped.score.precision, capped.score.precision);
  // Measured: 93 points, 11 in the bright third, without the cap; 191, 74, with it; all within
  // 5 cm of a line.
  EXPECT_GE(capped.bright, uncapped.bright + 40);
  EXPECT_GE(capped.score.precision, 0.99);
  EXPECT_LE(capped.score.median_error_m, 0.02);
}

/// A field colour with the turf's statistics set by hand (SpotThresholds reads no image).
FieldColor turf(float luma_sigma, float texture_sigma) {
  FieldColor color;
  color.valid = true;
  color.luma_sigma = luma_sigma;
  color.texture_sigma = texture_sigma;
  return color;
}

TEST(SaturatedLight, ThresholdsFollowTheHeadroomDownToTheTexturesFloor) {
  const CameraPreset nao_top = cameraPreset("nao-top");
  const LineWidthModel widths(CameraModel(nao_top.intrinsics, nao_top.robot_T_camera), 0.05);
  LineSpotConfig config;
  // Spread 34, texture 22 (a sunlit real frame's): 3.5 x 34 = 119 grey levels.
  const FieldColor color = turf(34.f, 22.f);
  const SpotThresholds thresholds(color, widths, config, cv::Size(640, 480));
  EXPECT_TRUE(thresholds.uniform());
  const int v = 400;
  // Dark turf: far more headroom than 119.
  EXPECT_EQ(thresholds.forPeak(60, v, 255), 119);
  // Turf at 165 leaves 90: a saturated peak is asked 0.75 x 90 = 67, another one 119.
  EXPECT_EQ(thresholds.forPeak(165, v, 255), 67);
  EXPECT_EQ(thresholds.forPeak(165, v, config.headroom_min_peak_luma), 67);
  EXPECT_EQ(thresholds.forPeak(165, v, config.headroom_min_peak_luma - 1), 119);
  // Turf at 215 leaves 40, but its texture asks 3 x 22 = 66.
  EXPECT_EQ(thresholds.forPeak(215, v, 255), 66);
  // The scan's threshold is the saturated peak's.
  EXPECT_EQ(thresholds.saturated(165, v), 67);
  // No cap: one threshold.
  config.headroom_share = 0.0;
  const SpotThresholds uncapped(color, widths, config, cv::Size(640, 480));
  EXPECT_EQ(uncapped.forPeak(165, v, 255), 119);
  EXPECT_EQ(uncapped.saturated(215, v), 119);
}

}  // namespace
}  // namespace houghloc
