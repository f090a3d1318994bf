#include "vision/vision_pipeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <ostream>
#include <stdexcept>
#include <string>

#include "vision/image_conversion.h"
#include "vision/line_width_model.h"
#include "vision_test_views.h"

namespace houghloc {
namespace {

using testing::PointScore;
using testing::TestView;

struct ViewCase {
  const char* preset;
  const char* field;
  Pose2 pose;
  size_t min_points;
};

void PrintTo(const ViewCase& c, std::ostream* os) { *os << c.preset << "/" << c.field; }

std::vector<Eigen::Vector2d> groundOf(const VisionResult& result) {
  std::vector<Eigen::Vector2d> points;
  for (const GroundPoint& p : result.ground.points) points.push_back(p.p_robot);
  return points;
}

VisionConfig configFor(const TestView& view) {
  VisionConfig config;
  config.line_width_m = view.field.line_width;
  return config;
}

class PipelineOnViews : public ::testing::TestWithParam<ViewCase> {};

TEST_P(PipelineOnViews, PointsLieOnTheLines) {
  const ViewCase& c = GetParam();
  testing::SyntheticStyle style;
  style.gradient = 0.35;
  style.noise_sigma = 4.0;
  const TestView& view = testing::testView(c.preset, c.field, c.pose, style);
  VisionPipeline pipeline(view.preset.intrinsics, configFor(view));
  const VisionResult result = pipeline.process(view.image, view.preset.robot_T_camera, 42);
  EXPECT_EQ(result.ground.t_us, 42);
  const PointScore score = testing::scorePoints(view, groundOf(result));
  EXPECT_GE(score.points, c.min_points);
  EXPECT_GE(score.precision, 0.98);
  EXPECT_LE(score.median_error_m, 0.01);
  ASSERT_EQ(result.ground.visible_regions.size(), 1u);
  EXPECT_GE(result.ground.visible_regions[0].size(), 4u);
  for (const GroundPoint& p : result.ground.points) {
    EXPECT_LE(p.p_robot.norm(), pipeline.config().projection.max_range_m + 1e-9);
    EXPECT_GT(p.weight, 0.0);
  }
}

/// GroundPoints::field_edge lies on the carpet's edge (field plus border strip) at the view's
/// pose, along each sample's ray from the camera, within 3 of its sigmas (plus 2 cm for the
/// drawing's anti-aliasing); none on nao-bottom, whose image ends 1.2 m out.
TEST_P(PipelineOnViews, FieldEdgeLiesOnTheCarpetEdge) {
  const ViewCase& c = GetParam();
  const TestView& view = testing::testView(c.preset, c.field, c.pose);
  VisionPipeline pipeline(view.preset.intrinsics, configFor(view));
  const VisionResult result = pipeline.process(view.image, view.preset.robot_T_camera, 0);
  const Pose3& camera = view.preset.robot_T_camera;
  const Eigen::Vector2d camera_field = view.field_T_robot.transform({camera.x, camera.y});
  int within = 0;
  for (const FieldEdgePoint& e : result.ground.field_edge) {
    const Eigen::Vector2d ray = view.field_T_robot.transform(e.p_robot) - camera_field;
    const double edge = rangeToRectangle(camera_field, ray.normalized(),
                                         view.field.outerHalfLength(), view.field.outerHalfWidth());
    EXPECT_GT(e.range_sigma_m, 0.0);
    within += std::abs(ray.norm() - edge) <= 3.0 * e.range_sigma_m + 0.02;
  }
  if (std::string(c.preset) == "nao-bottom") {
    EXPECT_TRUE(result.ground.field_edge.empty());
  } else {
    EXPECT_GE(result.ground.field_edge.size(), 12u);
    EXPECT_GE(within, 0.9 * result.ground.field_edge.size());
  }
}

INSTANTIATE_TEST_SUITE_P(PresetsAndFields, PipelineOnViews,
                         ::testing::Values(ViewCase{"nao-top", "spl", Pose2(-2.0, -1.0, 0.5), 100},
                                           ViewCase{"nao-top", "kid", Pose2(2.5, 1.0, -0.3), 100},
                                           ViewCase{"nao-bottom", "spl", Pose2(-0.35, 0.2, 0.1),
                                                    10},
                                           ViewCase{"kid-wide", "kid", Pose2(-3.0, -1.5, 0.3), 100},
                                           ViewCase{"adult", "adult", Pose2(-3.0, -1.0, 0.2), 100},
                                           ViewCase{"adult", "msl", Pose2(-6.0, -3.0, 0.4), 30}));

const TestView& naoView() {
  testing::SyntheticStyle style;
  style.gradient = 0.3;
  style.noise_sigma = 3.0;
  return testing::testView("nao-top", "spl", Pose2(-2.0, -1.0, 0.5), style);
}

TEST(VisionPipeline, YuyvInputGivesTheSamePoints) {
  const TestView& view = naoView();
  VisionPipeline bgr_pipeline(view.preset.intrinsics, configFor(view));
  VisionPipeline yuyv_pipeline(view.preset.intrinsics, configFor(view));
  const VisionResult from_bgr = bgr_pipeline.process(view.image, view.preset.robot_T_camera);
  const VisionResult from_yuyv =
      yuyv_pipeline.process(bgrToYuyv(view.image), view.preset.robot_T_camera);
  const PointScore score = testing::scorePoints(view, groundOf(from_yuyv));
  EXPECT_GE(score.precision, 0.98);
  EXPECT_NEAR(static_cast<double>(from_yuyv.ground.size()),
              static_cast<double>(from_bgr.ground.size()), 0.15 * from_bgr.ground.size());
}

TEST(VisionPipeline, WhiteObjectsOnTheFieldGiveNoPoints) {
  const TestView& view = naoView();
  cv::Mat image = view.image.clone();
  const CameraModel camera(view.preset.intrinsics, view.preset.robot_T_camera);
  // A ball (0.1 m) and a robot's white leg (0.12 m wide, 0.5 m tall) on open turf.
  const auto pixel = [&](double x, double y, double z) {
    const auto p = camera.project({x, y, z});
    return cv::Point(static_cast<int>(p->x()), static_cast<int>(p->y()));
  };
  const cv::Point ball = pixel(1.0, -0.2, 0.05);
  const int ball_radius = pixel(1.0, -0.25, 0.05).x - ball.x;
  cv::circle(image, ball, std::abs(ball_radius), cv::Scalar(240, 240, 240), cv::FILLED,
             cv::LINE_AA);
  cv::rectangle(image, pixel(1.3, 0.5, 0.5), pixel(1.3, 0.38, 0.0), cv::Scalar(235, 235, 235),
                cv::FILLED);
  VisionPipeline pipeline(view.preset.intrinsics, configFor(view));
  const VisionResult result = pipeline.process(image, view.preset.robot_T_camera);
  const PointScore score = testing::scorePoints(view, groundOf(result));
  EXPECT_GE(score.precision, 0.98);
  EXPECT_GE(score.points, 30u);
}

/// Accepted spots within radius_px of an image point.
int spotsWithin(const VisionResult& result, const cv::Point& centre, int radius_px) {
  int n = 0;
  for (const LineSpot& spot : result.spots) {
    n += std::hypot(spot.pixel.x() - centre.x, spot.pixel.y() - centre.y) <= radius_px ? 1 : 0;
  }
  return n;
}

/// The bottom camera's view of the SPL field with a ball drawn at (x, y) on the ground (robot
/// frame): white, black patches in the middle and at four places around it.
struct BallView {
  const TestView& view;
  cv::Mat image;
  cv::Point centre;
  int radius = 0;  ///< px
};

BallView ballAtTheFeet(double ball_x, double ball_y) {
  testing::SyntheticStyle style;
  style.noise_sigma = 2.0;
  const TestView& view = testing::testView("nao-bottom", "spl", Pose2(-1.0, 0.0, 0.3), style);
  const CameraModel camera(view.preset.intrinsics, view.preset.robot_T_camera);
  const auto pixel = [&](double x, double y, double z) {
    const auto p = camera.project({x, y, z});
    return cv::Point(static_cast<int>(std::lround(p->x())), static_cast<int>(std::lround(p->y())));
  };
  BallView ball{view, view.image.clone(), pixel(ball_x, ball_y, 0.05), 0};
  ball.radius = std::abs(pixel(ball_x, ball_y - 0.05, 0.05).x - ball.centre.x);
  cv::circle(ball.image, ball.centre, ball.radius, cv::Scalar(235, 235, 235), cv::FILLED,
             cv::LINE_AA);
  for (const cv::Point& offset :
       {cv::Point(0, 0), cv::Point(-1, -1), cv::Point(1, -1), cv::Point(-1, 1), cv::Point(1, 1)}) {
    cv::circle(ball.image, ball.centre + offset * (ball.radius * 6 / 10), ball.radius / 4,
               cv::Scalar(30, 30, 30), cv::FILLED, cv::LINE_AA);
  }
  return ball;
}

TEST(VisionPipeline, ABallAtTheFeetGivesNoPointsButTheLinesDo) {
  // The bottom camera sees a ball 0.35 m ahead about as wide as a line there; its white patches
  // between black ones and its rim against the turf are runs of a line's width with turf beside
  // them. What tells them from a line is that they do not go on in the scanlines beside them.
  const BallView ball = ballAtTheFeet(0.35, 0.12);
  const TestView& view = ball.view;
  const cv::Mat& image = ball.image;
  const cv::Point& centre = ball.centre;
  const int radius = ball.radius;
  VisionConfig config = configFor(view);
  config.spots.ball.enabled = false;  // the continuation test alone (the ball test: below)
  VisionPipeline pipeline(view.preset.intrinsics, config);
  const VisionResult result = pipeline.process(image, view.preset.robot_T_camera);
  config.spots.continuation.enabled = false;
  VisionPipeline without(view.preset.intrinsics, config);
  const VisionResult result_without = without.process(image, view.preset.robot_T_camera);
  const int on_ball = spotsWithin(result, centre, radius + 2);
  const int on_ball_without = spotsWithin(result_without, centre, radius + 2);
  std::printf("spots on the ball: %d (%d without the continuation test); points: %zu (%zu)\n",
              on_ball, on_ball_without, result.ground.size(), result_without.ground.size());
  EXPECT_GT(on_ball_without, 0);  // the case the test is for
  EXPECT_EQ(on_ball, 0);
  const PointScore score = testing::scorePoints(view, groundOf(result));
  EXPECT_GE(score.precision, 0.98);
  EXPECT_GE(static_cast<double>(result.ground.size()), 0.9 * result_without.ground.size());
}

TEST(VisionPipeline, TheBallTestAloneDropsTheSpotsOfABall) {
  // The same ball at the feet, with the continuation test off: the ball test (ball_spots.h)
  // finds the round blob with dark patches around each of its chords, and leaves the lines.
  const BallView ball = ballAtTheFeet(0.4, -0.15);
  const TestView& view = ball.view;
  const cv::Mat& image = ball.image;
  const cv::Point& centre = ball.centre;
  const int radius = ball.radius;
  VisionConfig config = configFor(view);
  config.spots.continuation.enabled = false;
  const VisionResult with_ball_test =
      VisionPipeline(view.preset.intrinsics, config).process(image, view.preset.robot_T_camera);
  config.spots.ball.enabled = false;
  const VisionResult without =
      VisionPipeline(view.preset.intrinsics, config).process(image, view.preset.robot_T_camera);
  const int on_ball = spotsWithin(with_ball_test, centre, radius + 2);
  const int on_ball_without = spotsWithin(without, centre, radius + 2);
  std::printf("spots on the ball: %d (%d without the ball test), %d dropped as on a ball\n",
              on_ball, on_ball_without, with_ball_test.diagnostics.spot_stats.on_ball);
  EXPECT_GT(on_ball_without, 0);  // the case the test is for
  EXPECT_EQ(on_ball, 0);
  EXPECT_GE(with_ball_test.diagnostics.spot_stats.on_ball, on_ball_without);
  // Every spot it drops lies on the ball: the others are the same.
  EXPECT_EQ(with_ball_test.spots.size() + on_ball_without, without.spots.size());
  EXPECT_GE(testing::scorePoints(view, groundOf(with_ball_test)).precision, 0.98);
}

TEST(VisionPipeline, DarkPixelsDoNotHideTheLinesBehindThem) {
  // Dark specks (a robot's joints, the shadow under a foot) in a row across the turf beyond
  // the far lines and in a column down its left side, so that most scanlines pass one before
  // they reach the lines. A run rising from a dark pixel is no line, and it must not swallow
  // what lies behind it (LineSpotConfig::dark_run_turf_px). With the run ending only at the
  // next dark pixel, as when dark_run_turf_px is longer than any scanline, most lines go unseen.
  const TestView& view = naoView();
  VisionConfig config = configFor(view);
  const VisionResult clean = VisionPipeline(view.preset.intrinsics, config)
                                 .process(view.image, view.preset.robot_T_camera);
  int field_top = view.image.rows;  // the highest spot: the far lines
  for (const LineSpot& spot : clean.spots) {
    field_top = std::min(field_top, static_cast<int>(spot.pixel.y()));
  }
  cv::Mat image = view.image.clone();
  const cv::Scalar dark(25, 25, 25);
  for (int u = 0; u < image.cols; u += 6) cv::rectangle(image, {u, field_top, 5, 3}, dark, -1);
  for (int v = field_top; v < image.rows; v += 6) cv::rectangle(image, {10, v, 3, 5}, dark, -1);
  const VisionResult result =
      VisionPipeline(view.preset.intrinsics, config).process(image, view.preset.robot_T_camera);
  config.spots.dark_run_turf_px = image.rows + image.cols;
  const VisionResult swallowed =
      VisionPipeline(view.preset.intrinsics, config).process(image, view.preset.robot_T_camera);
  std::printf("points: %zu without the specks, %zu with them, %zu when runs from them swallow\n",
              clean.ground.size(), result.ground.size(), swallowed.ground.size());
  // Measured 212, 195 and 105 points.
  EXPECT_LT(static_cast<double>(swallowed.ground.size()), 0.6 * clean.ground.size());  // the case
  EXPECT_GE(static_cast<double>(result.ground.size()), 0.85 * clean.ground.size());
  EXPECT_GE(testing::scorePoints(view, groundOf(result)).precision, 0.98);
}

TEST(VisionPipeline, DegenerateImagesGiveFewPoints) {
  const TestView& view = naoView();
  VisionPipeline pipeline(view.preset.intrinsics, configFor(view));
  const cv::Size size = view.image.size();
  cv::Mat noise(size, CV_8UC3);
  cv::randu(noise, cv::Scalar::all(0), cv::Scalar::all(255));
  for (const cv::Mat& image : {cv::Mat(cv::Mat::zeros(size, CV_8UC3)),
                               cv::Mat(size, CV_8UC3, cv::Scalar::all(255)), noise}) {
    EXPECT_LE(pipeline.process(image, view.preset.robot_T_camera).ground.size(), 5u);
  }
  // Sky only: the camera pitched 40 deg up sees no ground at all.
  Pose3 up = view.preset.robot_T_camera;
  up.pitch = -0.7;
  const VisionResult sky = pipeline.process(view.image, up);
  EXPECT_EQ(sky.ground.size(), 0u);
  EXPECT_TRUE(sky.ground.visible_regions.empty());
}

/// The nao-top view of the SPL field from (x, 0) with its camera pitch recorded as 0 (a nominal
/// pose on a robot whose head is pitched down): the lines lie above the recorded horizon.
struct LevelRecordedView {
  const TestView& view;
  Pose3 recorded;    ///< the camera pose with pitch 0
  double error_rad;  ///< the real pitch the recorded pose lacks
};
LevelRecordedView levelRecordedView(double x_m) {
  testing::SyntheticStyle style;
  style.noise_sigma = 3.0;
  const TestView& view = testing::testView("nao-top", "spl", Pose2(x_m, 0.0, 0.0), style);
  Pose3 recorded = view.preset.robot_T_camera;
  const double error_rad = recorded.pitch;
  recorded.pitch = 0.0;
  return {view, recorded, error_rad};
}

/// The pipeline with the field top's pitch taken as exact (no shortfall allowed for).
VisionConfig boundOnly(const TestView& view) {
  VisionConfig config = configFor(view);
  config.field_top_pitch.max_shortfall_rad = 0.0;
  return config;
}

TEST(VisionPipeline, LinesAboveTheRecordedHorizonAreFoundWithThePitchTheFieldAsksFor) {
  // The image of a camera pitched 20.6 deg down, recorded as looking straight ahead (a nominal
  // pose on a robot whose head is pitched): every line lies above the recorded horizon, so the
  // first scan sees turf only. The field's top seen above that horizon bounds the pitch: the
  // frame is scanned again with the horizon just above the far border, and the lines give points;
  // their widths then tell how much steeper than the bound the camera looks.
  const auto [view, recorded, error_rad] = levelRecordedView(1.0);
  // A bound, not the pitch: the carpet's far edge (4.14 m ahead of the camera) lies 6.9 deg below
  // the horizon, where the stage assumes border_depression_rad (2.9 deg).
  const VisionConfig bound_only = boundOnly(view);
  VisionPipeline bounded(view.preset.intrinsics, bound_only);
  const double camera_x = view.field_T_robot.x + recorded.x;
  const double border_depression = std::atan2(recorded.z, view.field.outerHalfLength() - camera_x);
  const double bound =
      error_rad - border_depression + bound_only.field_top_pitch.border_depression_rad;
  const VisionResult at_bound = bounded.process(view.image, recorded);
  EXPECT_NEAR(at_bound.diagnostics.field_top_pitch_rad, bound, 1.0 * M_PI / 180);

  VisionPipeline pipeline(view.preset.intrinsics, configFor(view));
  const VisionResult result = pipeline.process(view.image, recorded);
  const VisionDiagnostics& diag = result.diagnostics;
  std::printf(
      "pitch asked for %.1f deg (error %.1f deg, bound %.1f deg), %zu points (%zu at the "
      "bound)\n",
      diag.field_top_pitch_rad * 180 / M_PI, error_rad * 180 / M_PI, bound * 180 / M_PI,
      result.ground.size(), at_bound.ground.size());
  EXPECT_NEAR(diag.field_top_pitch_rad, error_rad, 1.0 * M_PI / 180);
  EXPECT_GE(result.ground.size(), 20u);
  // The points, projected with that pitch, lie on the lines (at the bound alone, 4 deg short,
  // they lay 10-40 % too far: median 0.37 m).
  const PointScore score = testing::scorePoints(view, groundOf(result), 0.5);
  std::printf("within 0.5 m of a line: %.2f, median distance %.3f m\n", score.precision,
              score.median_error_m);
  EXPECT_GE(score.precision, 0.9);
  EXPECT_LE(score.median_error_m, 0.1);
  // Without the field's top the frame stays empty: the first scan has no candidate to fit.
  VisionConfig without = configFor(view);
  without.field_top_pitch.enabled = false;
  VisionPipeline plain(view.preset.intrinsics, without);
  EXPECT_TRUE(plain.process(view.image, recorded).ground.points.empty());
}

TEST(VisionPipeline, LinesWiderThanTheFieldTopBoundSaysGiveItsShortfall) {
  // The view of the test above from 2.5 m: the carpet's far edge lies 2.6 m ahead, 10.9 deg below
  // the horizon, so the bound is 8 deg short of the real pitch and the lines are too wide for it.
  // Runs as wide as a line under the bound plus max_shortfall_rad (6.6 deg) pass the width test,
  // and their widths give the pitch within that range.
  const auto [view, recorded, error_rad] = levelRecordedView(2.5);
  VisionPipeline bounded(view.preset.intrinsics, boundOnly(view));
  const VisionResult at_bound = bounded.process(view.image, recorded);
  VisionPipeline pipeline(view.preset.intrinsics, configFor(view));
  const VisionResult result = pipeline.process(view.image, recorded);
  const PointScore score = testing::scorePoints(view, groundOf(result), 0.5);
  std::printf(
      "at the bound %.1f deg: %zu points, %d too wide; with its shortfall: %.1f deg "
      "(error %.1f deg), %zu points, %d too wide, within 0.5 m of a line %.2f\n",
      at_bound.diagnostics.field_top_pitch_rad * 180 / M_PI, at_bound.ground.size(),
      at_bound.diagnostics.spot_stats.too_wide, result.diagnostics.field_top_pitch_rad * 180 / M_PI,
      error_rad * 180 / M_PI, result.ground.size(), result.diagnostics.spot_stats.too_wide,
      score.precision);
  EXPECT_LE(at_bound.ground.size(), 10u);
  EXPECT_GE(at_bound.diagnostics.spot_stats.too_wide, 100);
  EXPECT_NEAR(
      result.diagnostics.field_top_pitch_rad,
      at_bound.diagnostics.field_top_pitch_rad + configFor(view).field_top_pitch.max_shortfall_rad,
      1.0 * M_PI / 180);
  EXPECT_GE(result.ground.size(), 50u);
  EXPECT_GE(score.precision, 0.9);
}

TEST(VisionPipeline, SpecksBelowTheRecordedHorizonDoNotHideTheLinesAboveIt) {
  // The frame of the test above with three white specks painted on the turf below the
  // recorded horizon, each a line's width tall for that pose and three widths long: the first
  // scan finds spots on them but no line (no segment, no arc), which is what a frame whose
  // horizon cuts below its lines shows when a ball, a robot's part or a bright tuft lies on the
  // turf. Such a frame is scanned again like a frame without spots.
  const auto [view, recorded, error_rad] = levelRecordedView(1.0);
  const CameraModel camera(view.preset.intrinsics, recorded);
  const LineWidthModel widths(camera, view.field.line_width, configFor(view).line_width);
  cv::Mat image = view.image.clone();
  for (const cv::Point centre : {cv::Point(150, 420), cv::Point(330, 380), cv::Point(500, 440)}) {
    const int tall = static_cast<int>(std::lround(widths.expectedPx(centre.x, centre.y).y()));
    const cv::Point half(3 * tall / 2, tall / 2);
    cv::rectangle(image, centre - half, centre + half, cv::Scalar(235, 235, 235), cv::FILLED);
  }

  VisionConfig without = configFor(view);
  without.field_top_pitch.enabled = false;
  VisionPipeline plain(view.preset.intrinsics, without);
  const VisionResult first_scan = plain.process(image, recorded);
  std::printf("without the field top: %zu points, %zu segments\n", first_scan.ground.size(),
              first_scan.features.segments.size());
  ASSERT_GE(first_scan.ground.size(), 3u);            // the specks give spots ...
  ASSERT_TRUE(first_scan.features.segments.empty());  // ... but no line
  ASSERT_TRUE(first_scan.features.circles.empty());

  VisionPipeline pipeline(view.preset.intrinsics, configFor(view));
  const VisionResult result = pipeline.process(image, recorded);
  const PointScore score = testing::scorePoints(view, groundOf(result), 0.5);
  std::printf("with it: pitch asked for %.1f deg, %zu points, within 0.5 m of a line %.2f\n",
              result.diagnostics.field_top_pitch_rad * 180 / M_PI, result.ground.size(),
              score.precision);
  EXPECT_GT(result.diagnostics.field_top_pitch_rad, 10.0 * M_PI / 180);
  EXPECT_GE(result.ground.size(), 20u);
  EXPECT_GE(score.precision, 0.9);
}

TEST(VisionPipeline, BadInputThrowsAClearError) {
  const TestView& view = naoView();
  VisionPipeline pipeline(view.preset.intrinsics, configFor(view));
  Pose3 nan_pose = view.preset.robot_T_camera;
  nan_pose.pitch = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(pipeline.process(view.image, nan_pose), std::invalid_argument);
  nan_pose = view.preset.robot_T_camera;
  nan_pose.z = std::numeric_limits<double>::infinity();
  EXPECT_THROW(pipeline.process(view.image, nan_pose), std::invalid_argument);
  cv::Mat small;
  cv::resize(view.image, small, {320, 240});
  try {
    pipeline.process(small, view.preset.robot_T_camera);
    FAIL() << "no exception for a 320x240 image";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("320x240"), std::string::npos) << e.what();
  }
  EXPECT_THROW(pipeline.process(cv::Mat(480, 640, CV_8UC1), view.preset.robot_T_camera),
               std::invalid_argument);
}

}  // namespace
}  // namespace houghloc
