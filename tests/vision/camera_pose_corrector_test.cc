#include "vision/camera_pose_corrector.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "field_models/angles.h"
#include "field_models/standard_fields.h"
#include "vision/camera_presets.h"
#include "vision/line_width_model.h"

namespace houghloc {
namespace {

CameraPoseCorrectionConfig enabledConfig() {
  CameraPoseCorrectionConfig config;
  config.enabled = true;  // the default; explicit because these tests are about it
  return config;
}

/// Segments of a field-line grid (lines every 1.5 m in both field directions, turned by
/// `heading`) in front of the robot, as the corrector gets them: camera-frame end rays from the
/// true camera pose, with the noise of a fitted segment on the ground.
std::vector<GroundSegment> gridSegments(const Pose3& true_pose, double heading, std::mt19937* rng) {
  std::normal_distribution<double> noise(0.0, 0.002);
  const Eigen::Matrix3d camera_R_robot = true_pose.rotation().transpose();
  const Eigen::Vector3d camera(true_pose.x, true_pose.y, true_pose.z);
  const Eigen::Vector2d along(std::cos(heading), std::sin(heading));
  const Eigen::Vector2d across(-along.y(), along.x());
  std::vector<GroundSegment> segments;
  for (int family = 0; family < 2; ++family) {
    const Eigen::Vector2d d = family == 0 ? along : across, n = family == 0 ? across : along;
    for (int k = -2; k <= 2; ++k) {
      // The part of the line 1-4 m ahead.
      const Eigen::Vector2d c = 2.5 * Eigen::Vector2d::UnitX() + (1.5 * k + 0.3) * n;
      GroundSegment s;
      s.a = c - 0.6 * d + noise(*rng) * n;
      s.b = c + 0.6 * d + noise(*rng) * n;
      if (s.a.x() < 1.0 || s.b.x() < 1.0) continue;
      s.num_points = 30;
      s.rms_m = 0.002;
      s.ray_a_camera = camera_R_robot * (Eigen::Vector3d(s.a.x(), s.a.y(), 0.0) - camera);
      s.ray_b_camera = camera_R_robot * (Eigen::Vector3d(s.b.x(), s.b.y(), 0.0) - camera);
      segments.push_back(s);
    }
  }
  return segments;
}

TEST(CameraPoseCorrector, RecoversAConstantPitchAndRollError) {
  const Pose3 true_pose = cameraPreset("nao-top").robot_T_camera;
  Pose3 recorded = true_pose;
  recorded.roll += 1.0 * kDeg;
  recorded.pitch += 2.0 * kDeg;
  CameraPoseCorrector corrector(enabledConfig());
  std::mt19937 rng(5);
  for (int frame = 0; frame < 20; ++frame) {
    corrector.update(gridSegments(true_pose, 0.3 + 0.05 * frame, &rng), recorded);
  }
  EXPECT_NEAR(corrector.correction().x(), -1.0 * kDeg, 0.05 * kDeg);
  EXPECT_NEAR(corrector.correction().y(), -2.0 * kDeg, 0.05 * kDeg);
  const Pose3 corrected = corrector.corrected(recorded);
  EXPECT_NEAR(corrected.pitch, true_pose.pitch, 0.05 * kDeg);
}

TEST(CameraPoseCorrector, LeavesAnExactPoseAlone) {
  const Pose3 true_pose = cameraPreset("nao-top").robot_T_camera;
  CameraPoseCorrector corrector(enabledConfig());
  std::mt19937 rng(6);
  for (int frame = 0; frame < 20; ++frame) {
    corrector.update(gridSegments(true_pose, -0.2 + 0.04 * frame, &rng), true_pose);
    EXPECT_EQ(corrector.correction(), Eigen::Vector2d::Zero()) << frame;
  }
  EXPECT_LT(corrector.estimate().norm(), 0.1 * kDeg);
}

/// The centre circle (radius 0.75 m) centred at `center` (robot frame) as one arc candidate:
/// camera-frame rays of 24 points on its near half, from the true camera pose.
CircleCandidate circleArc(const Pose3& true_pose, const Eigen::Vector2d& center) {
  const Eigen::Matrix3d camera_R_robot = true_pose.rotation().transpose();
  const Eigen::Vector3d camera(true_pose.x, true_pose.y, true_pose.z);
  CircleCandidate arc;
  arc.center = center;
  arc.radius_m = 0.75;
  for (int i = 0; i < 24; ++i) {
    const double a = 0.5 * M_PI + M_PI * i / 23.0;  // the half facing the robot
    const Eigen::Vector2d p = center + 0.75 * Eigen::Vector2d(std::cos(a), std::sin(a));
    arc.rays_camera.push_back(camera_R_robot * (Eigen::Vector3d(p.x(), p.y(), 0.0) - camera));
  }
  return arc;
}

TEST(CameraPoseCorrector, RecoversTheTiltFromCentreCircleArcsAlone) {
  const Pose3 true_pose = cameraPreset("nao-top").robot_T_camera;
  Pose3 recorded = true_pose;
  recorded.roll += 1.0 * kDeg;
  recorded.pitch += 2.0 * kDeg;
  CameraPoseCorrectionConfig config = enabledConfig();
  config.circle_radius_m = 0.75;
  CameraPoseCorrector corrector(config);
  for (int frame = 0; frame < 8; ++frame) {
    corrector.update({}, {circleArc(true_pose, {2.0, -0.6 + 0.15 * frame})}, recorded);
  }
  EXPECT_NEAR(corrector.correction().x(), -1.0 * kDeg, 0.02 * kDeg);
  EXPECT_NEAR(corrector.correction().y(), -2.0 * kDeg, 0.02 * kDeg);
  // Without the map's radius the arcs are not used.
  CameraPoseCorrector no_radius(enabledConfig());
  EXPECT_FALSE(no_radius.update({}, {circleArc(true_pose, {2.0, 0.0})}, recorded));
}

TEST(CameraPoseCorrector, WaitsForEnoughFramesAndIgnoresSingleLines) {
  const Pose3 true_pose = cameraPreset("nao-top").robot_T_camera;
  Pose3 recorded = true_pose;
  recorded.pitch += 2.0 * kDeg;
  CameraPoseCorrector corrector(enabledConfig());
  std::mt19937 rng(7);
  std::vector<GroundSegment> one = gridSegments(true_pose, 0.3, &rng);
  one.resize(1);
  for (int frame = 0; frame < 5; ++frame) EXPECT_FALSE(corrector.update(one, recorded));
  corrector.update(gridSegments(true_pose, 0.3, &rng), recorded);
  EXPECT_EQ(corrector.correction(), Eigen::Vector2d::Zero());  // one frame < min_frames
}

/// The interpolated width model against the camera model's exact widths, for every preset at
/// its mount pose, including the steep NAO bottom camera whose horizon lies above the image.
/// Line points of `field` that a camera at field_T_robot sees 0.5-4 m ahead (within +-30 deg),
/// one every 5 cm, as spot rays of the true camera pose with 1 mm ground noise.
std::vector<SpotRay> mapSpotRays(const FieldModel& field, const Pose2& field_T_robot,
                                 const Pose3& true_pose, std::mt19937* rng) {
  std::normal_distribution<double> noise(0.0, 0.001);
  const Eigen::Matrix3d camera_R_robot = true_pose.rotation().transpose();
  const Eigen::Vector3d camera(true_pose.x, true_pose.y, true_pose.z);
  const Pose2 robot_T_field = field_T_robot.inverse();
  std::vector<SpotRay> rays;
  for (const Segment2& segment : field.segments) {
    const int steps = static_cast<int>(segment.length() / 0.05);
    for (int k = 0; k <= steps; ++k) {
      const Eigen::Vector2d p_field = segment.a + (segment.b - segment.a) * k / std::max(1, steps);
      Eigen::Vector2d p = robot_T_field.transform(p_field);
      p += Eigen::Vector2d(noise(*rng), noise(*rng));
      if (p.norm() < 0.5 || p.norm() > 4.0 || std::abs(std::atan2(p.y(), p.x())) > 0.5) continue;
      SpotRay ray;
      ray.ray_camera = camera_R_robot * (Eigen::Vector3d(p.x(), p.y(), 0.0) - camera);
      rays.push_back(ray);
    }
  }
  return rays;
}

/// The robot walks through the SPL penalty area, the localizer's pose a few cm off.
TEST(CameraPoseCorrector, MatchingPointsToTheMapPinsTheTiltDown) {
  const FieldModel field = makeStandardField("spl");
  const Pose3 true_pose = cameraPreset("nao-top").robot_T_camera;
  Pose3 recorded = true_pose;
  recorded.roll += 1.0 * kDeg;
  recorded.pitch += 2.0 * kDeg;
  CameraPoseCorrector with_map(enabledConfig()), without_map(enabledConfig());
  with_map.setFieldModel(std::make_shared<const FieldModel>(field));
  std::mt19937 rng(9);
  int matched_frames = 0;
  for (int frame = 0; frame < 30; ++frame) {
    const Pose2 field_T_robot(-2.2 - 0.04 * frame, 0.8 - 0.03 * frame, 2.8 + 0.02 * frame);
    const std::vector<SpotRay> rays = mapSpotRays(field, field_T_robot, true_pose, &rng);
    const Pose2 localizer_pose = field_T_robot * Pose2(0.03, -0.02, 0.01);
    const std::vector<GroundSegment> segments = gridSegments(true_pose, 0.1 * frame, &rng);
    with_map.update(segments, {}, recorded, {&rays, localizer_pose});
    without_map.update(segments, {}, recorded);
    if (with_map.lastMapInliers() > 0) ++matched_frames;
  }
  EXPECT_GE(matched_frames, 20);
  const Eigen::Vector2d truth(-1.0 * kDeg, -2.0 * kDeg);
  const double error_with = (with_map.correction() - truth).cwiseAbs().maxCoeff();
  const double error_without = (without_map.correction() - truth).cwiseAbs().maxCoeff();
  EXPECT_LT(error_with, 0.003 * kDeg);
  EXPECT_LT(error_with, 0.5 * error_without);
}

/// Rays of the camera at `pose` to robot-frame ground points.
std::vector<Eigen::Vector3d> raysTo(const std::vector<Eigen::Vector2d>& points, const Pose3& pose) {
  std::vector<Eigen::Vector3d> rays;
  for (const Eigen::Vector2d& p : points) {
    rays.push_back(pose.rotation().transpose() *
                   (Eigen::Vector3d(p.x(), p.y(), 0.0) - pose.translation()));
  }
  return rays;
}

/// A frame's points show a tilt only on two lines (or an arc) spread over 1 m: in a NAO's bottom
/// camera view, 0.4 m across, the fitted pose mimicked a tilt and gave a confident 2 deg on a
/// recording with exact extrinsics.
TEST(MapTiltObservation, NeedsTwoLinesSpreadOverAMetre) {
  const FieldModel field = makeStandardField("spl");
  // The penalty area's corner (-2.85, 2) lies 0.4 m ahead: one line runs to the robot's right
  // (robot y < 0), the other back toward the robot (robot x < 0.4).
  const Pose2 field_T_robot(-3.25, 2.0, 0.0);
  const auto points = [](double reach_m, bool both_lines) {
    std::vector<Eigen::Vector2d> out;
    for (double s = 0.0; s <= reach_m + 1e-9; s += reach_m / 8.0) {
      out.push_back({0.4, -s});                             // across, to the right
      if (both_lines) out.push_back({0.4 - 0.6 * s, 0.0});  // back along robot x
    }
    return out;
  };
  MapTiltConfig config;
  const Pose3 bottom = cameraPreset("nao-bottom").robot_T_camera;
  const auto inliers = [&](const std::vector<Eigen::Vector2d>& p, const Pose3& pose,
                           const MapTiltConfig& c) {
    MapTiltObservation observation(raysTo(p, pose), std::vector<double>(p.size(), 0.004),
                                   field_T_robot);
    return observation.associate(field, pose, c, 4.0);
  };
  const auto near_corner = points(0.3, true);  // 0.3 m x 0.18 m: a bottom camera's view
  EXPECT_EQ(inliers(near_corner, bottom, config), 0);
  MapTiltConfig no_spread = config;
  no_spread.min_spread_m = 0.0;
  EXPECT_EQ(inliers(near_corner, bottom, no_spread), static_cast<int>(near_corner.size()));
  const Pose3 top = cameraPreset("nao-top").robot_T_camera;
  const auto long_corner = points(1.5, true);
  EXPECT_EQ(inliers(long_corner, top, config), static_cast<int>(long_corner.size()));
  EXPECT_EQ(inliers(points(1.5, false), top, config), 0);  // one line, however long
}

TEST(CameraPoseCorrector, IgnoresAFieldPoseThatDoesNotFitTheLines) {
  const FieldModel field = makeStandardField("spl");
  const Pose3 true_pose = cameraPreset("nao-top").robot_T_camera;
  CameraPoseCorrector corrector(enabledConfig());
  corrector.setFieldModel(std::make_shared<const FieldModel>(field));
  std::mt19937 rng(10);
  // Points are matched only as far out as the lines alone pin the tilt down: no lines, no map.
  const Pose2 field_T_robot(-2.5, 0.5, 3.0);
  {
    const std::vector<SpotRay> rays = mapSpotRays(field, field_T_robot, true_pose, &rng);
    corrector.update({}, {}, true_pose, {&rays, field_T_robot});
    EXPECT_EQ(corrector.lastMapInliers(), 0);
  }
  for (int frame = 0; frame < 10; ++frame) {
    corrector.update(gridSegments(true_pose, 0.1 * frame, &rng), true_pose);
  }
  const std::vector<SpotRay> rays = mapSpotRays(field, field_T_robot, true_pose, &rng);
  ASSERT_GT(rays.size(), 40u);
  corrector.update({}, {}, true_pose, {&rays, field_T_robot});
  EXPECT_GT(corrector.lastMapInliers(), 30);  // the right pose: matched
  for (const Pose2& wrong :
       {field_T_robot * Pose2(0.8, 0.4, 0.0), field_T_robot * Pose2(0.0, 0.0, 0.3)}) {
    corrector.update({}, {}, true_pose, {&rays, wrong});
    EXPECT_EQ(corrector.lastMapInliers(), 0) << wrong.x << " " << wrong.y << " " << wrong.theta;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  corrector.update({}, {}, true_pose, {&rays, Pose2(nan, 0.0, 0.0)});
  EXPECT_EQ(corrector.lastMapInliers(), 0);
  EXPECT_EQ(corrector.correction(), Eigen::Vector2d::Zero());
}

TEST(LineWidthModel, MatchesTheCameraModelForEveryPreset) {
  for (const std::string& name : cameraPresetNames()) {
    const CameraPreset preset = cameraPreset(name);
    const CameraModel camera(preset.intrinsics, preset.robot_T_camera);
    const LineWidthModel model(camera, 0.05);
    double worst = 0.0;
    for (int v = 0; v < camera.height(); v += 9) {
      for (int u = 0; u < camera.width(); u += 17) {
        const auto exact = camera.expectedLineWidthPx(u, v, 0.05);
        const auto ground = camera.pixelToGround(u, v);
        if (!exact || !ground || ground->norm() > 5.0 || exact->y() < 1.0) continue;
        const Eigen::Vector2f m = model.expectedPx(static_cast<float>(u), static_cast<float>(v));
        worst = std::max(
            {worst, std::abs(m.x() / exact->x() - 1.0), std::abs(m.y() / exact->y() - 1.0)});
      }
    }
    EXPECT_LT(worst, 0.08) << name;
  }
}

}  // namespace
}  // namespace houghloc
