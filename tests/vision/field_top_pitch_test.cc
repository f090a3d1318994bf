#include "vision/field_top_pitch.h"

#include <gtest/gtest.h>

#include <cmath>

#include "vision/camera_presets.h"
#include "vision/horizon.h"

namespace houghloc {
namespace {

constexpr double kRadPerDeg = M_PI / 180.0;
const cv::Vec3b kTurfBgr(40, 140, 50);
const FieldColor kTurfColor = [] {
  FieldColor c;
  c.valid = true;
  c.r = 50.f / 230.f;
  c.g = 140.f / 230.f;
  c.radius = 0.05f;
  c.luma_median = 92.f;
  c.min_luma = 23.f;
  c.chroma_noise = 10.f;
  return c;
}();

/// What `truth` sees of flat turf that ends `border_m` ahead (grey beyond), above it a band of
/// `clutter` from the border up to `clutter_rows` above it: every pixel is back-projected with
/// the camera model, independent of the code under test.
cv::Mat turfView(const CameraModel& truth, double border_m, cv::Vec3b clutter = {120, 120, 120},
                 int clutter_rows = 0) {
  cv::Mat image(truth.height(), truth.width(), CV_8UC3, cv::Scalar(120, 120, 120));
  for (int u = 0; u < image.cols; ++u) {
    int top = image.rows;
    for (int v = image.rows - 1; v >= 0; --v) {
      const auto ground = truth.pixelToGround(u, v);
      if (!ground || ground->x() > border_m) break;
      image.at<cv::Vec3b>(v, u) = kTurfBgr;
      top = v;
    }
    for (int v = std::max(0, top - clutter_rows); v < top; ++v) image.at<cv::Vec3b>(v, u) = clutter;
  }
  return image;
}

/// The depression (rad) below the horizontal under which `camera` sees ground `range_m` ahead.
double depressionAt(const CameraModel& camera, double range_m) {
  return std::atan2(camera.pose().z, range_m - camera.pose().x);
}

TEST(FieldTopPitch, LiftsTheHorizonAboveTheFieldSeen) {
  const CameraPreset preset = cameraPreset("nao-top");
  const CameraModel truth(preset.intrinsics, preset.robot_T_camera);
  // 8 deg off: the border 4 m ahead lies 7.2 deg below the horizon, less than min_rise_rad above
  // the recorded one; nothing to say (the candidates' widths do, width_pitch.h).
  for (const double error_deg : {8.0, 12.0, 15.0, 20.0}) {
    Pose3 pose = preset.robot_T_camera;
    pose.pitch -= error_deg * kRadPerDeg;  // the recorded pose looks higher than the camera does
    const CameraModel recorded(preset.intrinsics, pose);
    const double border_m = 4.0;
    const cv::Mat image = turfView(truth, border_m);
    const FieldTopPitchConfig config;
    const std::optional<double> offset =
        pitchToSeeFieldTop(image, kTurfColor, recorded, scanStartRows(recorded), config);
    ASSERT_EQ(offset.has_value(), error_deg > 8.0) << error_deg;
    if (!offset) continue;
    // The horizon is lifted to the border seen 4 m ahead and config.border_depression_rad
    // beyond: the error less the border's depression, plus the assumed one.
    const double expected =
        error_deg * kRadPerDeg - depressionAt(truth, border_m) + config.border_depression_rad;
    EXPECT_NEAR(*offset / kRadPerDeg, expected / kRadPerDeg, 0.5) << error_deg;
  }
}

TEST(FieldTopPitch, NothingWhenTheFieldEndsBelowTheHorizon) {
  const CameraPreset preset = cameraPreset("nao-top");
  const CameraModel camera(preset.intrinsics, preset.robot_T_camera);
  const cv::Mat image = turfView(camera, 4.0);
  EXPECT_FALSE(pitchToSeeFieldTop(image, kTurfColor, camera, scanStartRows(camera), {}));
  // A pose 1 deg off lifts the field less than min_rise_rad above the computed horizon.
  Pose3 pose = preset.robot_T_camera;
  pose.pitch -= 1.0 * kRadPerDeg;
  const CameraModel slightly_off(preset.intrinsics, pose);
  EXPECT_FALSE(
      pitchToSeeFieldTop(image, kTurfColor, slightly_off, scanStartRows(slightly_off), {}));
  // Switched off, or without a field colour.
  pose.pitch -= 14.0 * kRadPerDeg;
  const CameraModel off_pose(preset.intrinsics, pose);
  FieldTopPitchConfig off;
  off.enabled = false;
  EXPECT_FALSE(pitchToSeeFieldTop(image, kTurfColor, off_pose, scanStartRows(off_pose), off));
  EXPECT_FALSE(pitchToSeeFieldTop(image, FieldColor{}, off_pose, scanStartRows(off_pose), {}));
  EXPECT_TRUE(pitchToSeeFieldTop(image, kTurfColor, off_pose, scanStartRows(off_pose), {}));
}

TEST(FieldTopPitch, DarkClutterBeyondTheBorderIsNotTurf) {
  // A dark curtain of the turf's hue right above the border (its chromaticity passes the field
  // colour's test, it is darker than min_luma_ratio of the turf): the offset stays the turf's.
  const CameraPreset preset = cameraPreset("nao-top");
  const CameraModel truth(preset.intrinsics, preset.robot_T_camera);
  Pose3 pose = preset.robot_T_camera;
  pose.pitch -= 15.0 * kRadPerDeg;
  const CameraModel recorded(preset.intrinsics, pose);
  const cv::Vec3b curtain(13, 45, 16);  // a third of the turf's brightness
  ASSERT_TRUE(kTurfColor.isField(curtain.val));
  const cv::Mat clear = turfView(truth, 4.0);
  const cv::Mat cluttered = turfView(truth, 4.0, curtain, 100);
  const std::optional<double> expected =
      pitchToSeeFieldTop(clear, kTurfColor, recorded, scanStartRows(recorded), {});
  const std::optional<double> offset =
      pitchToSeeFieldTop(cluttered, kTurfColor, recorded, scanStartRows(recorded), {});
  ASSERT_TRUE(expected && offset);
  EXPECT_NEAR(*offset / kRadPerDeg, *expected / kRadPerDeg, 0.3);
  // Counted as turf (no luma test), the curtain lifts it by its 100 rows (about 9 deg).
  FieldTopPitchConfig colour_only;
  colour_only.min_luma_ratio = 0.0;
  const std::optional<double> lifted =
      pitchToSeeFieldTop(cluttered, kTurfColor, recorded, scanStartRows(recorded), colour_only);
  ASSERT_TRUE(lifted);
  EXPECT_GT(*lifted - *offset, 5.0 * kRadPerDeg);
}

}  // namespace
}  // namespace houghloc
