#include "field_models/pose2.h"

#include <gtest/gtest.h>

#include <random>

namespace houghloc {
namespace {

constexpr double kPoseTol = 1e-12;

Pose2 randomPose(std::mt19937& rng) {
  std::uniform_real_distribution<double> xy(-10.0, 10.0), angle(-M_PI, M_PI);
  return Pose2(xy(rng), xy(rng), angle(rng));
}

void expectNear(const Pose2& a, const Pose2& b, double tol = kPoseTol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(angleDifference(a.theta, b.theta), 0.0, tol);
}

TEST(Pose2Test, ComposesByHand) {
  // Robot at (1, 2) facing +y; a point 1 m ahead of it is at (1, 3), still facing +y.
  const Pose2 field_T_robot(1.0, 2.0, M_PI / 2);
  const Pose2 robot_T_ahead(1.0, 0.0, 0.0);
  expectNear(field_T_robot * robot_T_ahead, Pose2(1.0, 3.0, M_PI / 2));
  const Eigen::Vector2d p = field_T_robot.transform({0.0, 1.0});  // 1 m to the robot's left
  EXPECT_NEAR(p.x(), 0.0, kPoseTol);
  EXPECT_NEAR(p.y(), 2.0, kPoseTol);
}

TEST(Pose2Test, InverseAndCompositionIdentities) {
  std::mt19937 rng(42);
  for (int i = 0; i < 200; ++i) {
    const Pose2 a = randomPose(rng), b = randomPose(rng), c = randomPose(rng);
    expectNear(a * a.inverse(), Pose2());
    expectNear(a.inverse() * a, Pose2());
    expectNear(a.inverse().inverse(), a, 1e-11);
    expectNear((a * b) * c, a * (b * c), 1e-11);
    expectNear((a * b).inverse(), b.inverse() * a.inverse(), 1e-11);
    const Eigen::Vector2d p(0.3 * i, -1.7);
    EXPECT_LT(((a * b).transform(p) - a.transform(b.transform(p))).norm(), 1e-11);
    EXPECT_LT((a.inverse().transform(a.transform(p)) - p).norm(), 1e-11);
    // The odometry increment (DESIGN §3) recovers the motion between two readings.
    const Pose2 odom_curr = a * b;
    expectNear(a.inverse() * odom_curr, b, 1e-11);
  }
}

TEST(Pose2Test, NormalizeAngleWrapsToHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(normalizeAngle(M_PI), M_PI);
  EXPECT_DOUBLE_EQ(normalizeAngle(-M_PI), M_PI);  // -pi is excluded, maps to pi
  EXPECT_NEAR(normalizeAngle(3.0 * M_PI), M_PI, kPoseTol);
  EXPECT_NEAR(normalizeAngle(2.0 * M_PI + 0.1), 0.1, kPoseTol);
  EXPECT_NEAR(normalizeAngle(-1.5 * M_PI), 0.5 * M_PI, kPoseTol);
  EXPECT_NEAR(normalizeAngle(-0.25), -0.25, 0.0);
  EXPECT_NEAR(normalizeAngle(1000.0), 1000.0 - 159.0 * 2.0 * M_PI, 1e-9);
  EXPECT_NEAR(angleDifference(M_PI - 0.1, -M_PI + 0.1), -0.2, kPoseTol);
  EXPECT_TRUE(std::isnan(normalizeAngle(std::nan(""))));

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> any(-100.0, 100.0);
  for (int i = 0; i < 1000; ++i) {
    const double a = any(rng);
    const double w = normalizeAngle(a);
    EXPECT_GT(w, -M_PI);
    EXPECT_LE(w, M_PI);
    const double turns = (a - w) / (2.0 * M_PI);  // a whole number of turns apart
    EXPECT_NEAR(turns, std::round(turns), 1e-12);
  }
  EXPECT_GT(Pose2(0.0, 0.0, 7.0).theta, 0.0);
  EXPECT_NEAR(Pose2(0.0, 0.0, 7.0).theta, 7.0 - 2.0 * M_PI, kPoseTol);
}

}  // namespace
}  // namespace houghloc
