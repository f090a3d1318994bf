#include "vision/ground_projection.h"

#include <gtest/gtest.h>

#include <cmath>

namespace houghloc {
namespace {

/// A NAO-like head camera: 0.5 m up, looking 20 deg down, turned 30 deg left, slightly rolled.
Pose3 headCamera() {
  Pose3 pose;
  pose.x = 0.05;
  pose.y = -0.02;
  pose.z = 0.5;
  pose.roll = 0.03;
  pose.pitch = 20.0 * M_PI / 180.0;
  pose.yaw = 30.0 * M_PI / 180.0;
  return pose;
}

/// The ground point of a camera-frame ray under `pose`, by central differences of the angle
/// `angle` (the reference the analytic Jacobian is checked against).
Eigen::Vector2d numericDerivative(const Eigen::Vector3d& ray, Pose3 pose, double Pose3::*angle) {
  const double h = 1e-6;
  const GroundProjectionConfig unlimited = unlimitedProjection();
  pose.*angle += h;
  const auto plus = rayToGround(ray, pose, unlimited);
  pose.*angle -= 2.0 * h;
  const auto minus = rayToGround(ray, pose, unlimited);
  EXPECT_TRUE(plus && minus);
  return (*plus - *minus) / (2.0 * h);
}

TEST(GroundProjection, TiltJacobianIsTheDerivativeOfTheGroundPoint) {
  const Pose3 pose = headCamera();
  const GroundProjector projector(pose);
  // Rays in the camera body frame (x forward, y left, z up) at several ranges and bearings.
  for (const Eigen::Vector3d& ray :
       {Eigen::Vector3d(1.0, 0.0, -0.05), Eigen::Vector3d(1.0, 0.4, -0.2),
        Eigen::Vector3d(1.0, -0.5, 0.1), Eigen::Vector3d(1.0, 0.1, -0.6)}) {
    const Eigen::Matrix2d jacobian = projector.tiltJacobian(ray);
    const Eigen::Vector2d d_roll = numericDerivative(ray, pose, &Pose3::roll);
    const Eigen::Vector2d d_pitch = numericDerivative(ray, pose, &Pose3::pitch);
    EXPECT_LT((jacobian.col(0) - d_roll).norm(), 1e-5 * (1.0 + d_roll.norm())) << ray.transpose();
    EXPECT_LT((jacobian.col(1) - d_pitch).norm(), 1e-5 * (1.0 + d_pitch.norm())) << ray.transpose();
  }
}

TEST(GroundProjection, PitchMovesAFarPointAlongItsRayByRangeSquaredOverHeight) {
  // Straight ahead, 2 m away, from 0.5 m up: (d^2 + h^2) / h = 8.5 m per rad, toward the robot
  // when the camera pitches further down.
  Pose3 pose;
  pose.z = 0.5;
  pose.pitch = std::atan2(0.5, 2.0);
  const Eigen::Matrix2d jacobian = GroundProjector(pose).tiltJacobian(Eigen::Vector3d::UnitX());
  EXPECT_NEAR(jacobian(0, 1), -8.5, 1e-9);
  EXPECT_NEAR(jacobian(1, 1), 0.0, 1e-9);
  // Roll turns the camera about its optical axis, which the ray lies on: the point stays.
  EXPECT_NEAR(jacobian.col(0).norm(), 0.0, 1e-12);
}

TEST(GroundProjection, ProjectedSpotsCarryTheirTiltJacobian) {
  const Pose3 pose = headCamera();
  const SpotRay spot{Eigen::Vector3d(1.0, 0.1, -0.3), Eigen::Vector2f(100.0F, 200.0F), false};
  const std::vector<GroundPoint> points = projectSpots({spot}, pose, 0, GroundProjectionConfig{});
  ASSERT_EQ(points.size(), 1U);
  EXPECT_EQ(points[0].tilt_jacobian, GroundProjector(pose).tiltJacobian(spot.ray_camera));
  EXPECT_GT(points[0].tilt_jacobian.norm(), 0.1);
}

}  // namespace
}  // namespace houghloc
