#include "vision/boundary_gap.h"

#include <gtest/gtest.h>

#include "vision/camera_presets.h"
#include "vision/circle_fit.h"
#include "vision/own_body.h"

namespace houghloc {
namespace {

/// The ray to a ground point (robot frame), as spotRays() would give it.
SpotRay rayTo(const CameraModel& camera, const Eigen::Vector2d& ground) {
  SpotRay ray;
  const Pose3& pose = camera.pose();
  ray.ray_camera = pose.rotation().transpose() * (Eigen::Vector3d(ground.x(), ground.y(), 0.0) -
                                                  Eigen::Vector3d(pose.x, pose.y, pose.z));
  ray.ray_camera.normalize();
  const auto pixel = camera.project(Eigen::Vector3d(ground.x(), ground.y(), 0.0));
  if (pixel) ray.pixel = pixel->cast<float>();
  return ray;
}

TEST(BoundaryGap, DropsSpotsJustBelowTheFieldsEndOnly) {
  const CameraPreset preset = cameraPreset("nao-top");
  const CameraModel camera(preset.intrinsics, preset.robot_T_camera);
  // The carpet ends 3.5 m ahead: the boundary row per column is that ground line's image.
  FieldBoundary boundary;
  boundary.found = true;
  boundary.rows.assign(static_cast<size_t>(camera.width()), 0.f);
  for (int u = 0; u < camera.width(); ++u) {
    for (int v = 0; v < camera.height(); ++v) {
      const auto g = camera.pixelToGround(u, v);
      if (g && g->x() < 3.5) {
        boundary.rows[static_cast<size_t>(u)] = static_cast<float>(v);
        break;
      }
    }
  }
  const std::vector<int> start_rows(static_cast<size_t>(camera.width()), 0);
  const std::vector<SpotRay> rays = {rayTo(camera, {3.3, 0.0}),    // a bar 0.2 m before the end
                                     rayTo(camera, {2.8, 0.3}),    // a line 0.7 m before it
                                     rayTo(camera, {1.5, -0.2})};  // near
  int dropped = 0;
  const auto kept = dropSpotsNearBoundary(rays, camera, boundary, start_rows, 0.45, 1.2, &dropped);
  EXPECT_EQ(dropped, 1);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].pixel, rays[1].pixel);
  // A boundary nearer than min_boundary_range_m (the carpet's end at 3.5 m against 3.6 m and
  // 3.4 m here; 1.2 m by default) is taken for an object on the field: nothing is dropped.
  EXPECT_EQ(dropSpotsNearBoundary(rays, camera, boundary, start_rows, 0.45, 3.6).size(), 3u);
  EXPECT_EQ(dropSpotsNearBoundary(rays, camera, boundary, start_rows, 0.45, 3.4).size(), 2u);
  // A boundary at the scan start row (the field reaches the image top) is no end of the field.
  boundary.rows.assign(boundary.rows.size(), 0.f);
  EXPECT_EQ(dropSpotsNearBoundary(rays, camera, boundary, start_rows, 0.45, 1.2).size(), 3u);
}

TEST(OwnBody, DropsSpotsOnTheFeetOnly) {
  const CameraPreset preset = cameraPreset("nao-bottom");
  const CameraModel camera(preset.intrinsics, preset.robot_T_camera);
  const std::vector<SpotRay> rays = {rayTo(camera, {0.13, 0.05}),  // a toe in a walking step
                                     rayTo(camera, {0.05, -0.1}),  // the other foot's side
                                     rayTo(camera, {0.16, 0.0}),   // a line just ahead
                                     rayTo(camera, {0.1, 0.13})};  // a line beside the feet
  int dropped = 0;
  const auto kept = dropSpotsOnOwnBody(rays, camera.pose(), OwnBodyConfig{}, &dropped);
  EXPECT_EQ(dropped, 2);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].pixel, rays[2].pixel);
  EXPECT_EQ(kept[1].pixel, rays[3].pixel);
  // A zero box keeps everything.
  EXPECT_EQ(dropSpotsOnOwnBody(rays, camera.pose(), OwnBodyConfig{0.0, 0.0, 0.0}).size(), 4u);
  EXPECT_FALSE(onOwnBody({0.15, 0.0}, OwnBodyConfig{}));
  EXPECT_TRUE(onOwnBody({-0.09, 0.1}, OwnBodyConfig{}));
}

TEST(CircleFit, FindsTheCentreOfAShortNoisyArcOfKnownRadius) {
  std::vector<Eigen::Vector2d> points;
  const Eigen::Vector2d center(1.2, -0.4);
  for (int i = 0; i < 20; ++i) {
    const double a = 0.3 + 0.05 * i;  // a 55 deg arc
    const double noise = (i % 2 ? 1.0 : -1.0) * 0.002;
    points.push_back(center + (0.75 + noise) * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  Eigen::Vector2d fitted;
  ASSERT_TRUE(fitCircleFixedRadius(points, 0.75, &fitted));
  EXPECT_LT((fitted - center).norm(), 0.005);
  EXPECT_FALSE(fitCircleFixedRadius({points[0], points[1]}, 0.75, &fitted));
}

}  // namespace
}  // namespace houghloc
