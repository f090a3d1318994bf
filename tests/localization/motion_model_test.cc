#include "localization/motion_model.h"

#include <gtest/gtest.h>

#include "localization/odometry_input.h"

namespace houghloc {
namespace {

TEST(MotionModel, PredictionMatchesHandComputedJacobians) {
  MotionModelConfig config;
  config = MotionModelConfig{};
  config.trans_var_per_m = 0.01;  // only the translation term, so the numbers stay simple
  config.trans_var_per_rad = config.rot_var_per_rad = config.rot_var_per_m = 0.0;
  config.trans_var_per_s = config.rot_var_per_s = 0.0;
  GaussianPose pose;
  pose.mean = Pose2(1.0, 2.0, M_PI / 2);
  pose.covariance = Eigen::Vector3d(0.01, 0.02, 0.03).asDiagonal();
  predictWithMotion(Pose2(0.1, 0.0, 0.0), 0.033, config, &pose);
  // Facing +y, 0.1 m forward moves +y. F(0,2) = -sin(theta) * 0.1 = -0.1; Q = 0.01 * 0.1 m^2.
  EXPECT_NEAR(pose.mean.x, 1.0, 1e-12);
  EXPECT_NEAR(pose.mean.y, 2.1, 1e-12);
  EXPECT_NEAR(pose.mean.theta, M_PI / 2, 1e-12);
  EXPECT_NEAR(pose.covariance(0, 0), 0.01 + 0.01 * 0.03 + 0.001, 1e-12);
  EXPECT_NEAR(pose.covariance(1, 1), 0.02 + 0.001, 1e-12);
  EXPECT_NEAR(pose.covariance(2, 2), 0.03, 1e-12);
  EXPECT_NEAR(pose.covariance(0, 2), -0.1 * 0.03, 1e-12);
  EXPECT_NEAR(pose.covariance(1, 2), 0.0, 1e-12);
}

TEST(MotionModel, UnknownMotionInflatesWithTimeAndStaysCapped) {
  MotionModelConfig config;
  GaussianPose pose;
  pose.covariance = Eigen::Matrix3d::Identity() * 1e-4;
  inflateUnknownMotion(2.0, config, &pose);
  EXPECT_NEAR(pose.covariance(0, 0), 1e-4 + 2.0 * config.unknown_trans_var_per_s, 1e-12);
  EXPECT_NEAR(pose.covariance(2, 2), 1e-4 + 2.0 * config.unknown_rot_var_per_s, 1e-12);
  inflateUnknownMotion(1e9, config, &pose);
  EXPECT_LE(pose.covariance(0, 0), config.max_sigma_xy_m * config.max_sigma_xy_m + 1e-9);
  EXPECT_LE(pose.covariance(2, 2), config.max_sigma_theta_rad * config.max_sigma_theta_rad + 1e-9);
  Eigen::Matrix3d bad = Eigen::Matrix3d::Constant(std::nan(""));
  sanitizeCovariance(config, &bad);
  EXPECT_TRUE(bad.allFinite());
}

TEST(OdometryInput, MotionIsThePoseCompositionNotTheDifference) {
  OdometryInput input;
  input.step(0, Pose2(1.0, 1.0, M_PI / 2));
  const MotionStep step = input.step(100000, Pose2(1.0, 1.05, M_PI / 2));
  ASSERT_TRUE(step.has_motion);
  EXPECT_NEAR(step.motion.x, 0.05, 1e-12);  // 5 cm forward in the robot frame
  EXPECT_NEAR(step.motion.y, 0.0, 1e-12);
  EXPECT_NEAR(step.dt_s, 0.1, 1e-12);
}

TEST(OdometryInput, DroppedAndNanReadingsLoseNothing) {
  OdometryInput input;
  input.step(0, Pose2(0.0, 0.0, 0.0));
  EXPECT_FALSE(input.step(33000, std::nullopt).has_motion);
  EXPECT_FALSE(input.step(66000, Pose2(std::nan(""), 0.0, 0.0)).has_motion);
  const MotionStep step = input.step(100000, Pose2(0.06, 0.0, 0.0));
  ASSERT_TRUE(step.has_motion);
  EXPECT_NEAR(step.motion.x, 0.06, 1e-12);
  EXPECT_EQ(step.unknown_s, 0.0);  // within the timeout nothing is unknown
}

TEST(OdometryInput, LongGapsJumpsAndBackwardTimeAreUnknownMotion) {
  OdometryInput input;
  input.step(0, Pose2(0.0, 0.0, 0.0));
  const MotionStep gap = input.step(1000000, std::nullopt);  // 1 s > timeout
  EXPECT_NEAR(gap.unknown_s, 1.0, 1e-12);
  const MotionStep jump = input.step(1033000, Pose2(50.0, 0.0, 0.0));
  EXPECT_TRUE(jump.jump);
  EXPECT_FALSE(jump.has_motion);
  EXPECT_GT(jump.unknown_s, 0.0);
  // The jump re-anchors: the next small step is believed again.
  EXPECT_TRUE(input.step(1066000, Pose2(50.01, 0.0, 0.0)).has_motion);
  const MotionStep back = input.step(500000, Pose2(50.02, 0.0, 0.0));
  EXPECT_TRUE(back.time_backwards);
  EXPECT_EQ(back.dt_s, 0.0);
  EXPECT_TRUE(back.motion.isFinite());
}

}  // namespace
}  // namespace houghloc
