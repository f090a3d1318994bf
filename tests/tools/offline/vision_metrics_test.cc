#include "tools/offline/vision_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "field_models/standard_fields.h"
#include "tools/offline/correction_summary.h"
#include "vision/camera_presets.h"

namespace houghloc {
namespace {

TEST(VisionMetrics, PrecisionRecallAndErrorsPerBand) {
  const FieldModel field = makeStandardField("spl");
  const CameraPreset preset = cameraPreset("nao-top");
  const CameraModel camera(preset.intrinsics, preset.robot_T_camera);
  const Pose2 field_T_robot(-2.5, 0.0, 0.0);  // halfway line 2.5 m ahead, across the view
  GroundPoints points;
  // Points on the halfway line (x_robot = 2.5) for |y| <= 0.5, 1 cm off, plus two far off.
  for (double y = -0.5; y <= 0.5001; y += 0.05) {
    GroundPoint p;
    p.p_robot = {2.51, y};
    points.points.push_back(p);
  }
  GroundPoint wrong;
  wrong.p_robot = {1.5, 0.3};
  points.points.push_back(wrong);
  wrong.p_robot = {3.5, -0.3};
  points.points.push_back(wrong);

  // The in-view part of the halfway line, sampled like the accumulator does (every 10 cm).
  int in_view = 0, near_points = 0;
  for (double y = -3.0; y <= 3.0001; y += 0.1) {
    const auto pixel = camera.project({2.5, y, 0.0});
    if (!pixel || !camera.inImage(*pixel) || std::hypot(2.5, y) >= 4.0) continue;
    ++in_view;
    if (std::abs(y) <= 0.595) ++near_points;  // within 10 cm of a point 1 cm off the line
  }
  ASSERT_GT(in_view, near_points);
  VisibleRecord visible;
  visible.feature = "segments[4]";
  visible.visible_length_m = 0.1 * in_view;
  ASSERT_NEAR(field.segments[4].a.x(), 0.0, 1e-9);  // segments[4] is the halfway line

  VisionMetricsAccumulator metrics(field);
  metrics.addFrame(points, field_T_robot, {visible}, camera);
  const VisionMetrics m = metrics.result();
  EXPECT_EQ(m.frames_scored, 1);
  EXPECT_EQ(m.points, 23);
  EXPECT_NEAR(m.precision, 21.0 / 23.0, 1e-9);
  ASSERT_EQ(m.bands.size(), 3u);
  EXPECT_EQ(m.bands[0].points, 1);
  EXPECT_EQ(m.bands[0].true_positives, 0);
  EXPECT_EQ(m.bands[1].points, 21);
  EXPECT_NEAR(m.bands[1].precision, 1.0, 1e-9);
  EXPECT_NEAR(m.bands[1].median_error_m, 0.01, 1e-6);
  EXPECT_NEAR(m.bands[1].recall, static_cast<double>(near_points) / in_view, 1e-9);
  EXPECT_NEAR(m.bands[1].visible_m, 0.1 * in_view, 1e-9);

  // Half of it occluded: the same detections now cover a larger share.
  visible.visible_length_m = 0.05 * in_view;
  VisionMetricsAccumulator occluded(field);
  occluded.addFrame(points, field_T_robot, {visible}, camera);
  EXPECT_NEAR(occluded.result().bands[1].recall,
              std::min(1.0, static_cast<double>(near_points) / (0.5 * in_view)), 1e-9);
  // Nothing visible: no recall denominator, precision still counted.
  VisionMetricsAccumulator none(field);
  none.addFrame(points, field_T_robot, {}, camera);
  EXPECT_EQ(none.result().bands[1].visible_m, 0.0);
  EXPECT_EQ(none.result().points, 23);
}

TEST(VisionMetrics, VisibleRowsAreMatchedByTimestamp) {
  std::vector<VisibleRecord> rows(3);
  rows[0].t_us = 5;
  rows[1].t_us = 7;
  rows[2].t_us = 7;
  EXPECT_EQ(visibleAt(rows, 7).size(), 2u);
  EXPECT_EQ(visibleAt(rows, 6).size(), 0u);
}

TEST(CorrectionSummary, CountsFramesFarFromTheFinalCorrection) {
  // A camera corrected from its third frame on (+2 deg pitch, then +2.3 deg), and a second
  // camera never corrected.
  const double deg = M_PI / 180.0;
  CorrectionSummary summary;
  const std::vector<Eigen::Vector2d> applied = {
      {0.0, 0.0}, {0.0, 0.0}, {0.0, 2.0 * deg}, {0.1 * deg, 2.3 * deg}, {0.0, 2.3 * deg}};
  for (const Eigen::Vector2d& a : applied) {
    VisionDiagnostics d;
    d.pose_correction_rad = a;
    summary.add("top", d);
    summary.add("bottom", VisionDiagnostics{});
  }
  // 0.3 and 0.1 deg off the final one are within 0.5 deg; the two uncorrected frames are not.
  EXPECT_EQ(summary.framesFarFromTheFinalCorrection("top"), 2);
  EXPECT_EQ(summary.framesFarFromTheFinalCorrection("bottom"), 0);
  EXPECT_EQ(summary.framesFarFromTheFinalCorrection("none"), 0);
}

}  // namespace
}  // namespace houghloc
