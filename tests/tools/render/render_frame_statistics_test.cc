// houghloc-frame-stats' measures (tools/realframes/frame_statistics.h), by which renders are
// compared with real frames, on synthetic images whose turf colour, noise, blur, vignetting and
// horizon are known.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "tests/tools/render/render_test_util.h"
#include "tools/realframes/frame_statistics.h"

namespace houghloc {
namespace {

constexpr int kWidth = 320, kHeight = 240;
const cv::Vec3f kTurfBgr(52.0f, 128.0f, 62.0f);
/// Every column sees the ground from the top row.
const std::vector<double> kAllGround(kWidth, -std::numeric_limits<double>::infinity());

/// Turf with grey noise of `noise` (the same on all channels, so luma noise is `noise`), a
/// vertical band of paint `contrast` brighter from column 150 to 165 when contrast > 0, blurred
/// with `blur` (Gaussian sigma, px), darkened by 1 - vignetting r^2 (r: corner distance 1).
cv::Mat3b turfImage(double noise, double contrast, double blur, double vignetting) {
  cv::Mat3f img(kHeight, kWidth, kTurfBgr);
  if (contrast > 0.0) img.colRange(150, 166) += cv::Scalar::all(contrast);
  if (blur > 0.0) cv::GaussianBlur(img, img, cv::Size(), blur);
  const double cx = 0.5 * (kWidth - 1), cy = 0.5 * (kHeight - 1), corner = std::hypot(cx, cy);
  cv::RNG rng(7);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const double r = std::hypot(x - cx, y - cy) / corner;
      const float n = static_cast<float>(rng.gaussian(noise));
      img(y, x) = img(y, x) * static_cast<float>(1.0 - vignetting * r * r) + cv::Vec3f(n, n, n);
    }
  }
  cv::Mat3b out;
  img.convertTo(out, CV_8UC3);
  return out;
}

TEST(RenderFrameStatistics, TurfColourAndNoiseOfFlatTurf) {
  const FrameStatistics s = measureFrame(turfImage(4.0, 0.0, 0.0, 0.0), kAllGround);
  const double sum = kTurfBgr[0] + kTurfBgr[1] + kTurfBgr[2];
  EXPECT_NEAR(s.turf_r, kTurfBgr[2] / sum, 0.005);
  EXPECT_NEAR(s.turf_g, kTurfBgr[1] / sum, 0.005);
  EXPECT_NEAR(s.turf_luma, 0.114 * 52 + 0.587 * 128 + 0.299 * 62, 1.0);
  // The MAD of 8-bit values moves in steps: 4.45 measured.
  EXPECT_NEAR(s.turf_luma_spread, 4.0, 0.6);
  EXPECT_NEAR(s.noise_sigma, 4.0, 0.15);  // 4.02 measured (8-bit rounding adds 1/12)
  EXPECT_GT(s.turf_share, 0.95);
  EXPECT_EQ(s.background_share, 0.0);
  EXPECT_NEAR(s.vignetting_ratio, 1.0, 0.02);
  EXPECT_TRUE(std::isnan(s.line_contrast));  // no paint in the image
}

TEST(RenderFrameStatistics, VignettingRatioLiesWithinTheRadialFalloff) {
  // Outer ring (r 0.8-1): gain 0.70-0.81; centre (r < 0.35): 0.96-1.
  const FrameStatistics s = measureFrame(turfImage(2.0, 0.0, 0.0, 0.3), kAllGround);
  EXPECT_GT(s.vignetting_ratio, 0.70);
  EXPECT_LT(s.vignetting_ratio, 0.84);
}

TEST(RenderFrameStatistics, LineContrastAndEdgeWidthFollowTheBlur) {
  const FrameStatistics sharp = measureFrame(turfImage(1.0, 100.0, 0.0, 0.0), kAllGround);
  const FrameStatistics soft = measureFrame(turfImage(1.0, 100.0, 1.5, 0.0), kAllGround);
  const FrameStatistics softer = measureFrame(turfImage(1.0, 100.0, 3.0, 0.0), kAllGround);
  EXPECT_NEAR(sharp.line_contrast, 100.0, 3.0);
  EXPECT_NEAR(soft.line_contrast, 100.0, 5.0);
  EXPECT_NEAR(sharp.line_share, 16.0 / kWidth, 0.01);
  // A step reads 2 px; a Gaussian edge sigma * sqrt(2 pi) (3.8 px at 1.5) over the slope
  // half a pixel from the edge.
  EXPECT_NEAR(sharp.edge_width_px, 2.0, 0.3);
  EXPECT_NEAR(soft.edge_width_px, 1.5 * std::sqrt(2.0 * M_PI), 0.6);
  EXPECT_NEAR(softer.edge_width_px, 3.0 * std::sqrt(2.0 * M_PI), 1.0);
  // A label mask gives the same paint.
  cv::Mat1b mask = cv::Mat1b::zeros(kHeight, kWidth);
  mask.colRange(150, 166).setTo(1);
  EXPECT_NEAR(measureFrame(turfImage(1.0, 100.0, 0.0, 0.0), kAllGround, mask).line_contrast, 100.0,
              3.0);
}

TEST(RenderFrameStatistics, BackgroundIsTheShareAboveTheHorizon) {
  const std::vector<double> horizon(kWidth, 59.5);  // rows 0-59 above: a quarter of 240
  const FrameStatistics s = measureFrame(turfImage(2.0, 0.0, 0.0, 0.0), horizon);
  EXPECT_DOUBLE_EQ(s.background_share, 0.25);
  EXPECT_GT(s.turf_share, 0.95);  // the turf above the horizon still has the turf's colour
}

/// The carpet, tint and hall options show in the statistics of a render (3 frames of the walk).
FolderStatistics renderAndMeasure(const std::string& name, const SceneConfig& scene,
                                  const SensorConfig& sensor, double tilt_deg) {
  RenderJob job = testJob("spl", "nao-top", name);
  job.scenario.frames = 3;
  job.scenario.scene = scene;
  job.scenario.sensor = sensor;
  job.scenario.head.tilt_deg = tilt_deg;
  renderRecording(job);
  return measureFolder(job.out_dir);
}

TEST(RenderFrameStatistics, CarpetTintAndHallOptionsShowInTheStatistics) {
  const FolderStatistics plain = renderAndMeasure("stats_plain", {}, {}, 0.0);
  SceneConfig grey;
  grey.turf_bgr = {95.0, 95.0, 95.0};
  const FolderStatistics carpet = renderAndMeasure("stats_grey", grey, {}, 0.0);
  SensorConfig magenta;
  magenta.tint = -0.8;
  const FolderStatistics tinted = renderAndMeasure("stats_tint", {}, magenta, 0.0);
  SceneConfig dark_hall;
  dark_hall.hall_brightness = 0.3;
  const FolderStatistics hall = renderAndMeasure("stats_hall", dark_hall, {}, -17.0);
  // Green turf by default; the grey carpet is grey (the default light is white).
  EXPECT_GT(plain.median.turf_g, 0.45);
  EXPECT_NEAR(carpet.median.turf_r, 1.0 / 3.0, 0.015);
  EXPECT_NEAR(carpet.median.turf_g, 1.0 / 3.0, 0.015);
  // Magenta: green gain exp(-0.2) = 0.82 on the whole image.
  EXPECT_LT(tinted.median.image_g, plain.median.image_g - 0.03);
  // Looking 3.6 deg down instead of 20.6 deg: about half the image above the horizon, and dark.
  EXPECT_LT(plain.median.background_share, 0.1);
  EXPECT_GT(hall.median.background_share, 0.35);
  EXPECT_LT(hall.median.image_luma, plain.median.image_luma);
}

}  // namespace
}  // namespace houghloc
