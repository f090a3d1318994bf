#include "tools/render/trajectory.h"

#include <gtest/gtest.h>

#include "field_models/standard_fields.h"
#include "tools/render/camera_rig.h"
#include "tools/render/odometry_model.h"

namespace houghloc {
namespace {

Scenario scenarioFor(const std::string& trajectory, int frames = 300) {
  Scenario s;
  s.trajectory.name = trajectory;
  s.frames = frames;
  return s;
}

TEST(TrajectoryTest, WalkStaysOnTheFieldAtWalkingSpeed) {
  const FieldModel field = makeStandardField("spl");
  const Scenario s = scenarioFor("walk");
  const Trajectory t(s, field);
  for (int i = 1; i < s.frames; ++i) {
    const Pose2 a = t.at((i - 1) / s.fps).field_T_robot, b = t.at(i / s.fps).field_T_robot;
    EXPECT_LE(std::abs(b.x), field.halfLength());
    EXPECT_LE(std::abs(b.y), field.halfWidth());
    EXPECT_NEAR((b.translation() - a.translation()).norm() * s.fps, s.trajectory.walk_speed_mps,
                0.01);
  }
}

TEST(TrajectoryTest, KidnapAndFallEvents) {
  const FieldModel field = makeStandardField("spl");
  const Trajectory kidnap(scenarioFor("kidnap"), field);
  ASSERT_EQ(kidnap.events().size(), 2u);
  EXPECT_EQ(kidnap.events()[0].event, "KIDNAP");
  const double tk = kidnap.events()[0].t_s;
  // The robot jumps, but the walked motion over the kidnap is an ordinary step.
  const Pose2 jump = kidnap.at(tk - 1.0 / 30).field_T_robot.inverse() * kidnap.at(tk).field_T_robot;
  EXPECT_GT(jump.translation().norm(), 0.5);
  EXPECT_LT(kidnap.walkedMotion(tk - 1.0 / 30, tk).translation().norm(), 0.02);

  const Scenario fs = scenarioFor("fall");
  const Trajectory fall(fs, field);
  ASSERT_EQ(fall.events().size(), 2u);
  EXPECT_EQ(fall.events()[0].event, "FALL_START");
  EXPECT_EQ(fall.events()[1].event, "FALL_END");
  const double mid = 0.5 * (fall.events()[0].t_s + fall.events()[1].t_s);
  const RobotState lying = fall.at(mid);
  EXPECT_GE(lying.fall_phase, 0.0);
  // Lying on its back the camera looks at the ceiling.
  const Pose3 cam = renderedCameraPose(Pose3{0.06, 0, 0.5, 0, 0.36, 0}, lying, mid, fs);
  EXPECT_GT((cam.rotation() * Eigen::Vector3d::UnitX()).z(), 0.5);
  EXPECT_LT(cam.z, 0.2);
}

TEST(TrajectoryTest, RandomPosesAreIndependentAndReproducible) {
  const FieldModel field = makeStandardField("kid");
  const Trajectory a(scenarioFor("random-poses"), field), b(scenarioFor("random-poses"), field);
  EXPECT_TRUE(a.independentFrames());
  for (int i = 0; i < 20; ++i) {
    const Pose2 p = a.at(i / 30.0).field_T_robot, q = b.at(i / 30.0).field_T_robot;
    EXPECT_EQ(p.x, q.x);
    EXPECT_EQ(p.theta, q.theta);
    EXPECT_LE(std::abs(p.x), field.halfLength() + 0.31);
  }
  EXPECT_NE(a.at(0.0).field_T_robot.x, a.at(1 / 30.0).field_T_robot.x);
}

TEST(OdometryModelTest, WithoutErrorsOdometryIsTheTrueMotion) {
  const FieldModel field = makeStandardField("spl");
  const Scenario s = scenarioFor("walk");
  const Trajectory t(s, field);
  OdometryConfig exact;
  exact.translation_noise = exact.rotation_noise = exact.rotation_per_metre_noise_deg = 0.0;
  exact.scale_bias = exact.rotation_bias = 0.0;
  exact.slip_rate_hz = 0.0;
  OdometryModel odo(exact, 1, s.fps);
  for (int i = 1; i < 200; ++i) odo.update(t.walkedMotion((i - 1) / s.fps, i / s.fps));
  const Pose2 truth = t.at(0.0).field_T_robot.inverse() * t.at(199 / s.fps).field_T_robot;
  EXPECT_NEAR(odo.pose().x, truth.x, 1e-9);
  EXPECT_NEAR(odo.pose().y, truth.y, 1e-9);
  EXPECT_NEAR(odo.pose().theta, truth.theta, 1e-9);
}

TEST(OdometryModelTest, NoiseGrowsLikeARandomWalk) {
  // 1 m straight ahead in 100 steps, many times: the spread of x is translation_noise.
  OdometryConfig c;
  c.scale_bias = 0.0;
  c.slip_rate_hz = 0.0;
  double sum = 0.0, sum2 = 0.0;
  const int runs = 400;
  for (int r = 0; r < runs; ++r) {
    OdometryModel odo(c, 100 + r, 30.0);
    for (int i = 0; i < 100; ++i) odo.update(Pose2(0.01, 0.0, 0.0));
    sum += odo.pose().x;
    sum2 += odo.pose().x * odo.pose().x;
  }
  const double mean = sum / runs, sd = std::sqrt(sum2 / runs - mean * mean);
  EXPECT_NEAR(mean, 1.0, 0.02);
  EXPECT_NEAR(sd, c.translation_noise, 0.015);
}

}  // namespace
}  // namespace houghloc
