// Far turf is smoother than near turf: its blades blur together. The spot threshold of rows of
// far turf comes from their own texture (FieldColor::band_texture_sigma,
// LineSpotConfig::far_turf_m_per_px), so the near turf's texture does not hide far, faint lines.
#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/core.hpp>
#include <vector>

#include "vision_test_views.h"

namespace houghloc {
namespace {

/// The texture's spread at the image's bottom row (grey levels); it falls linearly to
/// kFarShare of that at the top row.
constexpr double kNearTextureSigma = 14.0;
constexpr double kFarShare = 0.1;
/// The light falls from the far turf to the near (a hall's lamps beyond the field): a gradient
/// that spreads the turf's luma more than its texture.
constexpr double kFarBrightness = 1.3;
constexpr double kNearBrightness = 0.8;
/// Points this far from the robot or further are far (m).
constexpr double kFarRangeM = 3.0;

/// Turf texture (testing::turfTexture) that is strong near the camera
/// and faint far away.
cv::Mat withTextureFadingWithDistance(const cv::Mat& image) {
  cv::Mat noise = testing::turfTexture(image.size(), 11);
  cv::Mat out, noise3;
  image.convertTo(out, CV_32FC3);
  for (int v = 0; v < noise.rows; ++v) {
    const double near_share = static_cast<double>(v) / (noise.rows - 1);
    const double sigma = kNearTextureSigma * (kFarShare + (1.0 - kFarShare) * near_share);
    noise.row(v) *= sigma;
    out.row(v) *= kFarBrightness + (kNearBrightness - kFarBrightness) * near_share;
  }
  cv::merge(std::vector<cv::Mat>{noise, noise, noise}, noise3);
  out += noise3;
  out.convertTo(out, CV_8UC3);
  return out;
}

testing::VisionRun runWithFarTurf(const testing::TestView& view, const cv::Mat& image,
                                  double far_turf_m_per_px) {
  VisionConfig config;
  config.spots.far_turf_m_per_px = far_turf_m_per_px;
  return testing::runVision(view, image, config, kFarRangeM);
}

TEST(FarTurf, FaintFarLinesKeepTheirPoints) {
  // Dull grey paint: far, thin and anti-aliased, its lines rise less over the turf than the near
  // turf's texture allows for, but far more than the far turf's texture does.
  testing::SyntheticStyle style;
  style.noise_sigma = 1.0;
  style.line = cv::Vec3b(140, 140, 140);
  const testing::TestView& view =
      testing::testView("nao-top", "spl", Pose2(-2.0, -1.0, 0.5), style);
  const cv::Mat image = withTextureFadingWithDistance(view.image);
  const testing::VisionRun whole_turf = runWithFarTurf(view, image, 0.0),
                           far_bands =
                               runWithFarTurf(view, image, LineSpotConfig().far_turf_m_per_px);
  std::printf(
      "whole turf's texture: %zu points (%zu far), far bands' own: %zu (%zu), precision "
      "%.3f / %.3f\n",
      whole_turf.score.points, whole_turf.far, far_bands.score.points, far_bands.far,
      whole_turf.score.precision, far_bands.score.precision);
  // Measured: 83 points, 10 of them far, with the whole turf's texture; 115, 42 far, with the
  // far bands' own; all within 5 cm of a line.
  EXPECT_GE(far_bands.far, whole_turf.far + 25);
  EXPECT_GE(far_bands.score.precision, 0.99);
  EXPECT_LE(far_bands.score.median_error_m, 0.02);
}

TEST(FarTurf, EvenTextureKeepsOneThreshold) {
  // Turf as textured far as near: no band is smoother than the whole, the same points.
  testing::SyntheticStyle style;
  style.noise_sigma = 6.0;
  const testing::TestView& view =
      testing::testView("nao-top", "spl", Pose2(-2.0, -1.0, 0.5), style);
  const testing::VisionRun whole_turf = runWithFarTurf(view, view.image, 0.0),
                           far_bands =
                               runWithFarTurf(view, view.image, LineSpotConfig().far_turf_m_per_px);
  EXPECT_GT(whole_turf.score.points, 100u);
  EXPECT_EQ(far_bands.score.points, whole_turf.score.points);
  EXPECT_EQ(far_bands.score.median_error_m, whole_turf.score.median_error_m);
}

}  // namespace
}  // namespace houghloc
