// Unit tests of the real-frame tools on synthetic images: the column-scan baseline, the mask
// measures, the frame-rejection classifier and the coverage overlay.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "tools/baselines/column_scan.h"
#include "tools/realframes/coverage_overlay.h"
#include "tools/realframes/mask_metrics.h"
#include "vision/camera_presets.h"
#include "vision/frame_rejection.h"

namespace houghloc {
namespace {

cv::Mat turfWithStripe(int top, int height) {
  cv::Mat image(120, 160, CV_8UC3, cv::Scalar(50, 150, 60));
  cv::rectangle(image, {0, top}, {159, top + height - 1}, cv::Scalar(235, 235, 235), cv::FILLED);
  return image;
}

TEST(ColumnScan, FindsANarrowWhiteRunBetweenGreenInEveryFourthColumn) {
  const std::vector<LineSpot> spots = columnScanSpots(turfWithStripe(60, 6));
  ASSERT_EQ(spots.size(), 40u);  // columns 2, 6, ..., 158
  for (const LineSpot& s : spots) {
    EXPECT_FLOAT_EQ(s.pixel.y(), 62.5f);  // rows 60-65
    EXPECT_FLOAT_EQ(s.width_px, 6.f);
    EXPECT_EQ(static_cast<int>(s.pixel.x()) % 4, 2);
  }
}

TEST(ColumnScan, RejectsWideRunsAndRunsWithoutGreen) {
  EXPECT_TRUE(columnScanSpots(turfWithStripe(30, 50)).empty());  // 50 px > max_run_px
  cv::Mat image = turfWithStripe(60, 6);
  cv::rectangle(image, {0, 66}, {159, 119}, cv::Scalar(40, 40, 160), cv::FILLED);  // red below
  EXPECT_TRUE(columnScanSpots(image).empty());
}

TEST(MaskMetrics, PrecisionAndRecallAgainstAHandMask) {
  cv::Mat labels(100, 200, CV_8U, cv::Scalar(2));
  cv::rectangle(labels, {0, 48}, {199, 52}, cv::Scalar(1), cv::FILLED);  // a 5 px line
  std::vector<Eigen::Vector2f> pixels;
  for (int u = 0; u < 100; u += 10) pixels.emplace_back(u, 50.f);  // left half, on the line
  pixels.emplace_back(50.f, 10.f);                                 // on the turf
  const MaskMetrics m = maskMetrics(labels, pixels);
  EXPECT_EQ(m.points, 11);
  EXPECT_NEAR(m.precision, 10.0 / 11.0, 1e-9);
  EXPECT_EQ(m.off_line_on_field, 1);
  // Skeleton: row 50, columns ~2-197; points reach up to column 90 + 16.
  ASSERT_GT(m.skeleton_pixels, 180);
  // (+- a few px: the thinning leaves short spurs at the rectangle's ends.)
  EXPECT_NEAR(m.recall, 107.0 / m.skeleton_pixels, 6.0 / m.skeleton_pixels);
}

TEST(FrameRejection, NamesTheStageThatLeftAFrameEmpty) {
  const CameraPreset preset = cameraPreset("nao-top");
  VisionPipeline pipeline(preset.intrinsics);
  cv::Mat grey(preset.intrinsics.image_height, preset.intrinsics.image_width, CV_8UC3,
               cv::Scalar(128, 128, 128));
  const VisionResult grey_result = pipeline.process(grey, preset.robot_T_camera);
  EXPECT_EQ(classifyFrame(grey_result), FrameRejection::kNoFieldColor);
  EXPECT_STREQ(frameRejectionName(FrameRejection::kNoFieldColor), "no field colour");
  // Plain turf: colour and boundary found, nothing rises above the contrast threshold.
  cv::Mat turf = grey.clone();
  turf.setTo(cv::Scalar(50, 150, 60));
  cv::randn(turf, cv::Scalar(50, 150, 60), cv::Scalar::all(3));
  VisionPipeline fresh(preset.intrinsics);
  EXPECT_EQ(classifyFrame(fresh.process(turf, preset.robot_T_camera)),
            FrameRejection::kNoCandidates);
  // Spots found, dropped later: near the boundary or on the feet first, the rest for want of
  // support (SpotSupportConfig).
  VisionResult dropped;
  dropped.diagnostics.field_color.valid = true;
  dropped.boundary.found = true;
  dropped.diagnostics.num_spots = 3;
  dropped.diagnostics.dropped_near_boundary = 1;
  dropped.diagnostics.dropped_isolated = 2;
  EXPECT_EQ(classifyFrame(dropped), FrameRejection::kIsolated);
  EXPECT_STREQ(frameRejectionName(FrameRejection::kIsolated), "spots each without another near it");
  dropped.diagnostics.dropped_near_boundary = 3;
  dropped.diagnostics.dropped_isolated = 0;
  EXPECT_EQ(classifyFrame(dropped), FrameRejection::kDroppedNearBorder);
  dropped.diagnostics.dropped_near_boundary = 1;
  EXPECT_EQ(classifyFrame(dropped), FrameRejection::kNotProjected);
}

TEST(CoverageOverlay, MarksCoveredAndMissedSamplesAndThePointsWhereTheCameraSeesThem) {
  const CameraPreset preset = cameraPreset("nao-top");  // 20.6 deg down, sees 0.6 m and beyond
  const CameraModel camera(preset.intrinsics, preset.robot_T_camera);
  const cv::Mat grey(camera.height(), camera.width(), CV_8UC3, cv::Scalar(90, 90, 90));
  // Two samples 2 m ahead, 0.6 m apart; one point 0.12 m beside the first (within 0.15 m).
  const Eigen::Vector2d covered(2.0, 0.3), missed(2.0, -0.3), point(2.0, 0.42);
  const cv::Mat overlay = coverageOverlay(grey, camera, {covered, missed}, {point}, 0.15);
  const auto colourAt = [&](const Eigen::Vector2d& ground) {
    const auto pixel = camera.project({ground.x(), ground.y(), 0.0});
    EXPECT_TRUE(pixel && camera.inImage(*pixel));
    const cv::Vec3b c = overlay.at<cv::Vec3b>(static_cast<int>(std::lround(pixel->y())),
                                              static_cast<int>(std::lround(pixel->x())));
    return cv::Scalar(c[0], c[1], c[2]);
  };
  EXPECT_EQ(colourAt(covered), kCoveredColour);
  EXPECT_EQ(colourAt(missed), kUncoveredColour);
  EXPECT_EQ(colourAt(point), kPointColour);
  // The frame itself is left as it was.
  EXPECT_EQ(cv::countNonZero(grey.reshape(1) != 90), 0);
}

}  // namespace
}  // namespace houghloc
