// The real frames with a ground-truth field pose (../shared/data/real, physar_nao_top:
// six spots, physar_nao_bottom: one with lines). First the measures on synthetic input with an
// independent expectation, then what the vision and --global-only meet on the real frames, each
// figure printed beside the naive column-scan baseline's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "field_models/standard_fields.h"
#include "tests/real/real_data.h"
#include "tools/realframes/groundtruth_report.h"
#include "vision/camera_presets.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------- the measures, synthetic input

std::vector<Eigen::Vector2d> toRobot(const Pose2& field_T_robot,
                                     const std::vector<Eigen::Vector2d>& p_field) {
  std::vector<Eigen::Vector2d> out;
  for (const Eigen::Vector2d& p : p_field) out.push_back(field_T_robot.inverse().transform(p));
  return out;
}

TEST(RealGroundTruthMetrics, PointsOnTheMapLinesHaveMedianZero) {
  const FieldModel field = makeStandardField("spl");
  const Pose2 field_T_robot(-2.0, 0.5, 0.3);
  std::vector<Eigen::Vector2d> on_lines;
  for (double y = -2.9; y <= 2.9; y += 0.3) on_lines.emplace_back(0.0, y);  // halfway line
  for (double x = -4.4; x <= 4.4; x += 0.4) on_lines.emplace_back(x, 3.0);  // touch line
  for (double a = 0.1; a < 6.2; a += 0.5)
    on_lines.emplace_back(0.75 * std::cos(a), 0.75 * std::sin(a));
  EXPECT_NEAR(medianMapDistance(field, field_T_robot, toRobot(field_T_robot, on_lines)), 0.0, 1e-9);
  EXPECT_TRUE(std::isnan(medianMapDistance(field, field_T_robot, {})));
}

TEST(RealGroundTruthMetrics, PointsShiftedOffALineGiveTheShiftAsMedian) {
  const FieldModel field = makeStandardField("spl");
  const Pose2 field_T_robot(1.0, -1.0, 2.0);
  // Beside the halfway line at 1.2 <= y <= 2.5 nothing else is nearer than 0.45 m (circle,
  // touch line), so the distance is the shift.
  std::vector<Eigen::Vector2d> shifted;
  for (double y = 1.2; y <= 2.5; y += 0.1) shifted.emplace_back(0.2, y);
  EXPECT_NEAR(medianMapDistance(field, field_T_robot, toRobot(field_T_robot, shifted)), 0.2, 1e-9);
  // An even count: the mean of the two middle distances (0.1 and 0.2).
  const std::vector<Eigen::Vector2d> four = {{0.0, 2.0}, {0.1, 2.0}, {-0.2, 2.0}, {0.3, 2.0}};
  EXPECT_NEAR(medianMapDistance(field, field_T_robot, toRobot(field_T_robot, four)), 0.15, 1e-9);
}

TEST(RealGroundTruthMetrics, CountsPointsBeyondTheGoalLines) {
  const FieldModel field = makeStandardField("spl");  // goal lines at x = +-4.5
  const Pose2 field_T_robot(3.0, 1.0, -2.5);
  const std::vector<Eigen::Vector2d> p_field = {{4.55, 0.0},  {4.59, 1.0}, {4.65, 0.0},
                                                {-4.7, -1.0}, {0.0, 0.0},  {-4.61, 2.0}};
  EXPECT_EQ(countBeyondGoalLine(field, field_T_robot, toRobot(field_T_robot, p_field), 0.1), 3);
  const GroundTruthMetrics m =
      groundTruthMetrics(field, field_T_robot, CameraModel(cameraPreset("nao-top").intrinsics, {}),
                         toRobot(field_T_robot, p_field));
  EXPECT_EQ(m.points, 6);
  EXPECT_EQ(m.beyond_goal, 3);
  EXPECT_DOUBLE_EQ(m.beyond_goal_share, 0.5);
}

TEST(RealGroundTruthMetrics, CoverageCountsSamplesWithAPointWithinTheRadius) {
  const std::vector<Eigen::Vector2d> samples = {{1.0, 0.0}, {2.0, 0.0}, {3.0, 0.0}};
  const std::vector<Eigen::Vector2d> points = {{1.1, 0.0}, {2.2, 0.0}, {3.0, 0.149}};
  EXPECT_EQ(countCoveredSamples(samples, points, 0.15), 2);  // 0.1 and 0.149 in, 0.2 out
  EXPECT_EQ(countCoveredSamples(samples, {}, 0.15), 0);
}

TEST(RealGroundTruthMetrics, VisibleSamplesLieInTheCameraViewWithinRange) {
  const FieldModel field = makeStandardField("spl");
  const CameraPreset preset = cameraPreset("nao-top");  // 20.6 deg down, sees 0.6 m and beyond
  const CameraModel camera(preset.intrinsics, preset.robot_T_camera);
  const Pose2 field_T_robot(0.0, 0.0, 0.0);  // at the centre mark, facing the opponent goal
  const std::vector<Eigen::Vector2d> visible = visibleLineSamples(field, field_T_robot, camera);
  ASSERT_FALSE(visible.empty());
  const auto has = [&](const Eigen::Vector2d& p) {
    for (const Eigen::Vector2d& v : visible)
      if ((v - p).norm() < 1e-9) return true;
    return false;
  };
  EXPECT_TRUE(has({2.85, 0.0}));    // penalty area front line, straight ahead
  EXPECT_TRUE(has({4.5, 0.0}));     // goal line, 4.5 m ahead
  EXPECT_FALSE(has({-2.85, 0.0}));  // behind
  EXPECT_FALSE(has({0.0, 3.0}));    // touch line, 90 deg to the left
  for (const Eigen::Vector2d& v : visible) {
    EXPECT_LE(v.norm(), 5.0);
    EXPECT_LT(std::abs(std::atan2(v.y(), v.x() - preset.robot_T_camera.x)), 40.0 * M_PI / 180.0);
  }
  // Points on every visible sample cover all of them; the same points give median 0.
  const GroundTruthMetrics m = groundTruthMetrics(field, field_T_robot, camera, visible);
  EXPECT_EQ(m.visible_samples, static_cast<int>(visible.size()));
  EXPECT_DOUBLE_EQ(m.coverage, 1.0);
  EXPECT_NEAR(m.median_distance_m, 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(groundTruthMetrics(field, field_T_robot, camera, {}).coverage, 0.0);
}

// ---------------------------------------------------------------- the real frames

const char* const kTop = "physar_nao_top";
const char* const kBottom = "physar_nao_bottom";

/// The scored frames of both physar folders at the recorded camera poses (computed once).
const std::vector<GroundTruthFrameReport>& physarFrames() {
  static const std::vector<GroundTruthFrameReport> frames = [] {
    const std::vector<RealFrameLabel> labels = readRealIndex(HOUGHLOC_REAL_DATA);
    std::vector<GroundTruthFrameReport> all;
    for (const char* folder : {kTop, kBottom}) {
      for (GroundTruthFrameReport& r : groundTruthFrames(
               HOUGHLOC_REAL_DATA, folder, runRealFolder(HOUGHLOC_REAL_DATA, labels, folder))) {
        all.push_back(std::move(r));
      }
    }
    printGroundTruthFrames(all);
    return all;
  }();
  return frames;
}

std::string stemOf(const GroundTruthFrameReport& r) { return fs::path(r.image).stem().string(); }

TEST(RealGroundTruthFrames, SevenFramesWithLinesHaveAGroundTruthPose) {
  REQUIRE_REAL_DATA();
  int top = 0, bottom = 0;
  for (const GroundTruthFrameReport& r : physarFrames()) {
    top += r.folder == kTop;
    bottom += r.folder == kBottom;
    EXPECT_GT(r.houghloc.points, 0) << stemOf(r);
    EXPECT_GT(r.houghloc.visible_samples, 0) << stemOf(r);
  }
  EXPECT_EQ(top, 6);
  EXPECT_EQ(bottom, 1);  // red1_punt2_bottom
}

TEST(RealGroundTruthFrames, PointToMapDistanceAndGoalLineAtTheRecordedPose) {
  REQUIRE_REAL_DATA();
  // The target is a median <= 0.10 m on each frame. The recorded chain leaves the
  // camera pitched 2.4-2.9 deg too little (the set's fit_dpitch), which moves a ground point at
  // range r by up to r^2 / h x dpitch (0.41 m camera height, 2.7 deg: 0.5 m at 2 m, 1.0 m at
  // 3 m). The folder run in one pass, in order: the first frames go uncorrected
  // (black1_point1_top and black1_point4_top, medians 0.23 and 0.25 m); from black1_point5_top
  // on the pitch/roll corrector applies what the frames so far say (0.016-0.037 m; from
  // red1_punt2 on before the sunlit lines had points, LineSpotConfig::headroom_share). With the
  // tilt learned over the folder first every top frame meets 0.10 m: see
  // RealGroundTruthGlobalOnly below.
  // Bounds: the measured medians (docs/vision.md) plus about 5 %, at least 0.01 m.
  const std::map<std::string, double> bound_m = {
      {"black1_point1_top", 0.24}, {"black1_point4_top", 0.26}, {"black1_point5_top", 0.045},
      {"red1_punt1_top", 0.03},    {"red1_punt2_top", 0.05},    {"red1_punt4_top", 0.035},
      {"red1_punt2_bottom", 0.22},  // bottom camera, 22 points at 0.5-1.5 m
  };
  for (const GroundTruthFrameReport& r : physarFrames()) {
    const auto bound = bound_m.find(stemOf(r));
    ASSERT_NE(bound, bound_m.end()) << stemOf(r);
    EXPECT_LE(r.houghloc.median_distance_m, bound->second) << stemOf(r);
    // No point lies more than 0.1 m beyond a goal line on any of the seven (measured: none).
    EXPECT_EQ(r.houghloc.beyond_goal, 0) << stemOf(r);
  }
}

TEST(RealGroundTruthFrames, VisibleLineCoverageAtTheRecordedPose) {
  REQUIRE_REAL_DATA();
  // Share of the map's line samples within 5 m in view with a point within 0.15 m, over the
  // seven frames (measured 0.619, the column scan 0.425; 0.600 before the scan reached a pitch
  // margin beyond its range, ScanGridConfig::range_pitch_margin_rad; 0.360 before the sunlit
  // lines had points; black1_point4_top's 87 points lie beside the lines at the recorded pitch,
  // 0.12 there). The far samples of the uncorrected frames are missed for the pitch bias above.
  const PooledCoverage all = pooledCoverage(physarFrames());
  ASSERT_GT(all.visible, 0);
  std::printf("coverage over the seven frames: %.3f (%ld of %ld samples), baseline %.3f\n",
              all.share(), all.covered, all.visible, all.baselineShare());
  EXPECT_GE(all.share(), 0.61);
}

std::vector<GlobalCheckFrame> globalCheck(bool add_fit_dpitch, bool pose_correction,
                                          bool learn_tilt_first = false) {
  PipelineConfig config;
  config.vision.pose_correction.enabled = pose_correction;
  GlobalCheckConfig check;
  check.add_fit_dpitch = add_fit_dpitch;
  check.learn_tilt_first = learn_tilt_first;
  return globalCheckAtGroundTruth(HOUGHLOC_REAL_DATA, kTop, config, check);
}

int hits(const std::vector<GlobalCheckFrame>& frames) {
  int n = 0;
  for (const GlobalCheckFrame& f : frames) n += f.hit_rank >= 0;
  return n;
}

TEST(RealGroundTruthGlobalOnly, FitDpitchWithoutThePitchCorrector) {
  REQUIRE_REAL_DATA();
  // The camera pitch the images want (cam_pitch + fit_dpitch) and the vision's pitch/roll
  // corrector off, so the roll stays as recorded. Measured 4 of 6 hits at 85ba6b1 and its
  // parent: black1_point5_top's nearest hypothesis 0.19 m / 4.7 deg off (0.15 m / 3.6 deg
  // before, from 28 points instead of 133), red1_punt4_top's 0.24 m / 6.0 deg. Since the field
  // colour memory keeps to one turf, 3 of 6: black1_point4_top's sunlit far arc and halfway line
  // have points (75 -> 99; cover 0.366 -> 0.639, median at the truth 0.054 -> 0.029 m), and its
  // best pose moved to 0.18 m / 4.5 deg from the truth (0.09 m / 0.8 deg before). With the
  // corrector on (its +0.6 deg roll, FitDpitchWithTheDefaultConfig) that frame hits at 0.05 m /
  // 1.2 deg. The issue's >= 4 of 6 is asserted at the recorded pose with the tilt learned first.
  const std::vector<GlobalCheckFrame> frames = globalCheck(true, false);
  printGlobalCheck("physar_nao_top, camera pitch + fit_dpitch, pitch corrector off", frames);
  ASSERT_EQ(frames.size(), 6u);
  EXPECT_GE(hits(frames), 3);
  for (const GlobalCheckFrame& f : frames) {
    EXPECT_LE(f.metrics.median_distance_m, 0.10) << f.image;  // measured 0.027-0.052
    EXPECT_EQ(f.metrics.beyond_goal, 0) << f.image;
  }
}

TEST(RealGroundTruthGlobalOnly, FitDpitchWithTheDefaultConfig) {
  REQUIRE_REAL_DATA();
  // As houghloc-offline --global-only runs a copy of the folder with cam_pitch + fit_dpitch:
  // the corrector pools the folder's frames and applies +0.4 deg pitch, +0.6 deg roll by the
  // end (significant from the red1 spots on); measured 5 of 6 (red1_punt1_top's nearest 0.23 m /
  // 7.0 deg; 6 of 6 before the field colour memory kept to one turf), medians 0.011-0.051 m.
  // Hits lie 0.01-0.10 m from the truth (0.01-0.14 m before 85ba6b1), so one may fall out with a
  // small change: 5 asserted.
  const std::vector<GlobalCheckFrame> frames = globalCheck(true, true);
  printGlobalCheck("physar_nao_top, camera pitch + fit_dpitch, default config", frames);
  ASSERT_EQ(frames.size(), 6u);
  EXPECT_GE(hits(frames), 5);
  for (const GlobalCheckFrame& f : frames) {
    EXPECT_LE(f.metrics.median_distance_m, 0.10) << f.image;
  }
}
TEST(RealGroundTruthGlobalOnly, RecordedPoseWithTheTiltLearnedFirstMeetsTheTargets) {
  REQUIRE_REAL_DATA();
  // The recorded camera poses, as houghloc-offline --global-only --learn-tilt-first runs the
  // folder: the vision sees all ten stills once first, so the pitch/roll corrector applies the
  // folder's estimate (+2.9 deg pitch, +1.0 deg roll, sigmas 0.06-0.08 deg) from the first
  // frame on. Measured 6 of 6 hits (0.05-0.09 m off), medians 0.014-0.084 m. In one pass the
  // first frames go uncorrected: 3 of 6 (houghloc-real-report prints both).
  // black1_point4_top's sunlit turf: while the field colour memory carried black1_point3_top's
  // shaded turf into it (a 1.5 x bonus for another cluster, 0.14 away in chromaticity), its
  // sunlit lines counted as not turf-bounded: 76 points, cover 0.364. Measured now 99, 0.687.
  const std::vector<GlobalCheckFrame> frames = globalCheck(false, true, true);
  printGlobalCheck("physar_nao_top, recorded camera pose, tilt learned first", frames);
  ASSERT_EQ(frames.size(), 6u);
  EXPECT_GE(hits(frames), 4);  // the issue's >= 4 of 6
  for (const GlobalCheckFrame& f : frames) {
    EXPECT_LE(f.metrics.median_distance_m, 0.10) << f.image;
    EXPECT_EQ(f.metrics.beyond_goal, 0) << f.image;
    if (f.image.find("black1_point4_top") != std::string::npos) {
      EXPECT_GE(f.metrics.coverage, 0.65) << f.image;
    }
  }
}

TEST(RealGroundTruthGlobalOnly, BothCamerasSharingTheTiltLearnedFirstMeetTheTargets) {
  REQUIRE_REAL_DATA();
  // Both physar folders as the one robot's two cameras (one top and one bottom image per spot),
  // with one pitch/roll corrector for both and the tilt learned over all twenty frames first:
  // the bottom camera's own three line frames never determine its tilt, but the error lies in
  // the body or head (the bottom frame wants the same +2.6 deg as the top ones). Measured: the
  // bottom frame's median 0.204 m (own corrector) -> 0.013 m; top medians 0.014-0.087 m, 6 of 6
  // top hits (0.008 m and 0.006-0.082 m before the field colour memory kept to one turf;
  // at c465553, with the turf's light levels: 0.009 m, 0.014-0.063 m, 5 of 6, the
  // sixth 0.15 m off; at 85ba6b1, with the saturated light's points: 0.013 m, 0.019-0.081 m,
  // 6 of 6; at 76f9a66, with the runs from dark pixels: 0.013 m, 0.016-0.089 m, 5 of 6, the
  // sixth black1_point4_top, 0.25 m off). The median <= 0.10 m holds on all seven frames
  // with lines.
  PipelineConfig config;
  config.vision.pose_correction.shared_between_cameras = true;
  GlobalCheckConfig check;
  check.learn_tilt_first = true;
  const std::vector<GlobalCheckFrame> frames = globalCheckAtGroundTruth(
      HOUGHLOC_REAL_DATA, std::vector<std::string>{kTop, kBottom}, config, check);
  printGlobalCheck("both physar cameras, one shared corrector, tilt learned first", frames);
  ASSERT_EQ(frames.size(), 12u);  // six spots, two cameras each
  int with_lines = 0, top_hits = 0;
  for (const GlobalCheckFrame& f : frames) {
    top_hits += f.folder == kTop && f.hit_rank >= 0;
    if (f.points == 0) continue;  // the bottom camera's five spots without a line in view
    ++with_lines;
    EXPECT_LE(f.metrics.median_distance_m, 0.10) << f.image;
    EXPECT_EQ(f.metrics.beyond_goal, 0) << f.image;
  }
  EXPECT_EQ(with_lines, 7);
  EXPECT_GE(top_hits, 4);  // the issue's >= 4 of 6
}

}  // namespace
}  // namespace houghloc
