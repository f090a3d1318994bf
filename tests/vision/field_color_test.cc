#include "vision/field_color.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace houghloc {
namespace {

/// Background strip on top, turf below with a left-to-right lighting gradient, a dark shadow,
/// some white lines; then a per-channel gain (colour temperature, exposure).
cv::Mat turfImage(const cv::Vec3d& gain) {
  cv::Mat image(240, 320, CV_8UC3);
  cv::RNG rng(7);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      cv::Vec3d colour(150, 130, 120);  // wall
      if (v >= 60) {
        const double light = 1.0 - 0.5 * u / image.cols;  // gradient
        const double shadow = (u < 100 && v > 150) ? 0.5 : 1.0;
        colour = cv::Vec3d(45, 150, 60) * light * shadow + cv::Vec3d::all(rng.gaussian(5.0));
      }
      for (int c = 0; c < 3; ++c)
        image.at<cv::Vec3b>(v, u)[c] = cv::saturate_cast<uchar>(colour[c] * gain[c]);
    }
  }
  cv::line(image, {0, 120}, {319, 110}, cv::Scalar(230 * gain[0], 230 * gain[1], 230 * gain[2]), 4);
  cv::line(image, {100, 239}, {160, 61}, cv::Scalar(230 * gain[0], 230 * gain[1], 230 * gain[2]),
           5);
  return image;
}

double share(const cv::Mat& image, const FieldColor& color, cv::Rect area, bool field) {
  int hits = 0;
  for (int v = area.y; v < area.y + area.height; ++v) {
    for (int u = area.x; u < area.x + area.width; ++u) {
      const uchar* p = image.ptr<uchar>(v) + 3 * u;
      hits += field ? color.isField(p) : color.isWhitish(p);
    }
  }
  return static_cast<double>(hits) / area.area();
}

class FieldColorLight : public ::testing::TestWithParam<cv::Vec3d> {};

TEST_P(FieldColorLight, FollowsGradientShadowTemperatureAndExposure) {
  const cv::Mat image = turfImage(GetParam());
  const FieldColor color = estimateFieldColor(image, std::vector<int>(image.cols, 0));
  ASSERT_TRUE(color.valid);
  // Turf: bright left, dark right, in the shadow.
  EXPECT_GT(share(image, color, {0, 125, 60, 20}, true), 0.97);
  EXPECT_GT(share(image, color, {250, 70, 60, 30}, true), 0.97);
  EXPECT_GT(share(image, color, {10, 170, 80, 60}, true), 0.95);
  // The wall and the lines are not turf; lines are white.
  EXPECT_LT(share(image, color, {0, 0, 320, 50}, true), 0.01);
  EXPECT_EQ(share(image, color, {10, 118, 1, 1}, true), 0.0);
  EXPECT_EQ(share(image, color, {10, 118, 1, 1}, false), 1.0);
  EXPECT_LT(share(image, color, {0, 125, 60, 20}, false), 0.01);
}

INSTANTIATE_TEST_SUITE_P(Light, FieldColorLight,
                         ::testing::Values(cv::Vec3d(1.0, 1.0, 1.0),    // neutral
                                           cv::Vec3d(0.7, 1.0, 1.3),    // warm light
                                           cv::Vec3d(1.3, 1.0, 0.75),   // cold light
                                           cv::Vec3d(0.6, 0.6, 0.6),    // under-exposed
                                           cv::Vec3d(1.5, 1.5, 1.5)));  // over-exposed

/// Turf with independent Gaussian noise of `noise` grey levels per channel, lit from 1.0 on the
/// left down to `darkest` on the right (a gradient across the columns only).
cv::Mat noisyTurf(double noise, double darkest) {
  cv::Mat image(240, 320, CV_8UC3);
  cv::RNG rng(11);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      const double light = 1.0 - (1.0 - darkest) * u / (image.cols - 1);
      for (int c = 0; c < 3; ++c) {
        const double base = cv::Vec3d(60, 170, 70)[c] * light;
        image.at<cv::Vec3b>(v, u)[c] = cv::saturate_cast<uchar>(base + rng.gaussian(noise));
      }
    }
  }
  return image;
}

TEST(FieldColor, TextureSigmaIsTheNoiseWithoutTheLight) {
  // Luma = (B + 2G + R) / 4 of independent channel noise: sqrt(1 + 4 + 1) / 4 x the noise.
  const double noise = 6.0, luma_noise = std::sqrt(6.0) / 4.0 * noise;  // 3.67 grey levels
  const FieldColor even = estimateFieldColor(noisyTurf(noise, 1.0), std::vector<int>(320, 0));
  ASSERT_TRUE(even.valid);
  EXPECT_NEAR(even.texture_sigma, luma_noise, 0.25 * luma_noise);
  EXPECT_NEAR(even.luma_sigma, luma_noise, 0.25 * luma_noise);
  // Lit from 100 % down to 40 % across the image: the whole-image spread is the light, the
  // spread between neighbours in a column (the same light) stays the noise.
  const FieldColor lit = estimateFieldColor(noisyTurf(noise, 0.4), std::vector<int>(320, 0));
  ASSERT_TRUE(lit.valid);
  EXPECT_NEAR(lit.texture_sigma, luma_noise, 0.25 * luma_noise);
  EXPECT_GT(lit.luma_sigma, 4.0 * lit.texture_sigma);
}

TEST(FieldColor, NoFieldInAGreyImage) {
  cv::Mat grey(120, 160, CV_8UC3, cv::Scalar(128, 128, 128));
  cv::randn(grey, cv::Scalar::all(128), cv::Scalar::all(3));
  EXPECT_FALSE(estimateFieldColor(grey, std::vector<int>(grey.cols, 0)).valid);
  const cv::Mat black = cv::Mat::zeros(120, 160, CV_8UC3);
  EXPECT_FALSE(estimateFieldColor(black, std::vector<int>(black.cols, 0)).valid);
}

TEST(FieldColor, SamplesOnlyBelowTheStartRows) {
  const cv::Mat image = turfImage({1, 1, 1});
  // Nothing below the start rows: no samples, no field.
  EXPECT_FALSE(estimateFieldColor(image, std::vector<int>(image.cols, image.rows)).valid);
}

}  // namespace
}  // namespace houghloc

namespace houghloc {
namespace {

/// A wall with a faint green tint fills the upper 65 % of the view, the turf the lower 35 %,
/// its chromaticity spreading from yellowish far away (top) to saturated green near (bottom):
/// no single histogram bin of the turf holds a tenth of the samples.
cv::Mat wallOverSpreadTurf() {
  cv::Mat image(240, 320, CV_8UC3);
  cv::RNG rng(3);
  for (int v = 0; v < image.rows; ++v) {
    const double t = (v - 156) / 83.0;  // 0 at the turf's top, 1 at the bottom
    const cv::Vec3d colour =
        v < 156 ? cv::Vec3d(150, 170, 155) : cv::Vec3d(70 - 30 * t, 140 + 40 * t, 110 - 50 * t);
    for (int u = 0; u < image.cols; ++u) {
      for (int c = 0; c < 3; ++c) {
        image.at<cv::Vec3b>(v, u)[c] = cv::saturate_cast<uchar>(colour[c] + rng.gaussian(3.0));
      }
    }
  }
  return image;
}

TEST(FieldColor, FindsTurfThatIsNotTheLargestRegion) {
  const cv::Mat image = wallOverSpreadTurf();
  const FieldColor color = estimateFieldColor(image, std::vector<int>(image.cols, 0));
  ASSERT_TRUE(color.valid);
  // The turf's spread (g 0.44-0.64) is wider than the largest radius: most of it is taken, the
  // faintly green wall (g 0.36) none of it.
  EXPECT_GT(color.g, 0.5f);
  EXPECT_GT(share(image, color, {0, 160, 320, 80}, true), 0.6);
  EXPECT_LT(share(image, color, {0, 0, 320, 150}, true), 0.01);
}

TEST(FieldColor, RemembersTheLastColourOnlyWhereTheFrameSupportsIt) {
  const cv::Mat turf = turfImage({1, 1, 1});
  const FieldColor previous = estimateFieldColor(turf, std::vector<int>(turf.cols, 0));
  ASSERT_TRUE(previous.valid);
  // A grey frame: the remembered turf colour has no support there and is not kept.
  cv::Mat grey(120, 160, CV_8UC3, cv::Scalar(128, 128, 128));
  cv::randn(grey, cv::Scalar::all(128), cv::Scalar::all(3));
  EXPECT_FALSE(estimateFieldColor(grey, std::vector<int>(grey.cols, 0), {}, &previous).valid);
  // The same turf frame with the memory gives the same colour.
  const FieldColor again = estimateFieldColor(turf, std::vector<int>(turf.cols, 0), {}, &previous);
  ASSERT_TRUE(again.valid);
  EXPECT_NEAR(again.g, previous.g, 5e-3);  // the refinement starts elsewhere
}

/// Turf of two colours side by side, both down to the image bottom: `left_share` of the columns
/// a dark teal green (chromaticity r 0.21, g 0.51), the rest a bright yellowish green (r 0.37,
/// g 0.46), 0.16 apart: turf in the shade of a hall's windows and turf in the sun.
cv::Mat shadeAndSun(double left_share) {
  cv::Mat image(120, 160, CV_8UC3);
  cv::RNG rng(11);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      const cv::Vec3d colour =
          u < left_share * image.cols ? cv::Vec3d(60, 110, 45) : cv::Vec3d(70, 190, 150);
      for (int c = 0; c < 3; ++c) {
        image.at<cv::Vec3b>(v, u)[c] = cv::saturate_cast<uchar>(colour[c] + rng.gaussian(3.0));
      }
    }
  }
  return image;
}

TEST(FieldColor, TakesThisFramesTurfOverARememberedColourOfAnotherCluster) {
  const std::vector<int> rows(160, 0);
  const FieldColor shade = estimateFieldColor(shadeAndSun(1.0), rows);
  ASSERT_TRUE(shade.valid);
  EXPECT_NEAR(shade.r, 0.21, 0.02);
  // 45 % shade, 55 % sun: the sun holds more of the frame, the remembered shade colour a share
  // that its bonus (1.5) would lift above the sun's. It is another cluster, so the sun wins.
  const cv::Mat both = shadeAndSun(0.45);
  const FieldColor alone = estimateFieldColor(both, rows);
  const FieldColor remembered = estimateFieldColor(both, rows, {}, &shade);
  ASSERT_TRUE(alone.valid);
  ASSERT_TRUE(remembered.valid);
  EXPECT_NEAR(alone.r, 0.37, 0.02);
  EXPECT_NEAR(remembered.r, alone.r, 1e-3);
  EXPECT_NEAR(remembered.g, alone.g, 1e-3);
  // When the shade holds most of the frame it stays, with or without the memory.
  const FieldColor mostly_shade = estimateFieldColor(shadeAndSun(0.6), rows, {}, &shade);
  ASSERT_TRUE(mostly_shade.valid);
  EXPECT_NEAR(mostly_shade.r, 0.21, 0.02);
}

TEST(FieldColor, TakesTheSameTurfInTheShadeAsASecondColour) {
  const std::vector<int> rows(160, 0);
  const cv::Rect shade_area(4, 4, 60, 112), sun_area(80, 4, 76, 112);
  // 45 % shade, 55 % sun: the sun is the field colour, the shade (0.16 away in chromaticity,
  // 1.85 times darker) the same turf under other light.
  const cv::Mat both = shadeAndSun(0.45);
  const FieldColor color = estimateFieldColor(both, rows);
  ASSERT_TRUE(color.valid);
  EXPECT_NEAR(color.r, 0.37, 0.02);
  ASSERT_GT(color.other_radius, 0.f);
  EXPECT_NEAR(color.other_r, 0.21, 0.02);
  EXPECT_NEAR(color.other_g, 0.51, 0.02);
  EXPECT_GT(share(both, color, sun_area, true), 0.95);
  EXPECT_GT(share(both, color, shade_area, true), 0.95);
  // Without the second colour the shade is no field.
  FieldColorConfig one_colour;
  one_colour.max_other_light_distance = 0.0;
  const FieldColor plain = estimateFieldColor(both, rows, one_colour);
  EXPECT_EQ(plain.other_radius, 0.f);
  EXPECT_LT(share(both, plain, shade_area, true), 0.05);
  // When the shade is the field colour, the brighter cluster is not taken: what is brighter than
  // the turf is more often a window or a sunlit wall.
  const cv::Mat mostly_shade = shadeAndSun(0.6);
  const FieldColor shade = estimateFieldColor(mostly_shade, rows);
  ASSERT_TRUE(shade.valid);
  EXPECT_NEAR(shade.r, 0.21, 0.02);
  EXPECT_EQ(shade.other_radius, 0.f);
  EXPECT_LT(share(mostly_shade, shade, cv::Rect(100, 4, 56, 112), true), 0.05);
}

}  // namespace
}  // namespace houghloc
