// The synthetic ground-point generator and the exhaustive grid-search reference.
#include <gtest/gtest.h>

#include <cmath>

#include "field_models/field_distance.h"
#include "field_models/standard_fields.h"
#include "tools/baselines/grid_search.h"
#include "tools/synthetic/synthetic_ground_points.h"
#include "tools/synthetic/visible_region.h"

namespace houghloc {
namespace {

TEST(Synthetic, PointsLieOnMapLinesInsideTheView) {
  const FieldModel field = makeStandardField("spl");
  const Pose2 truth(-1.0, 0.5, 0.3);
  SyntheticConfig config;
  config.outlier_share = 0.0;
  config.noise_sigma_m = 0.01;
  config.noise_per_m = 0.0;
  const SyntheticFrame f = generateFrame(field, truth, config);
  ASSERT_GT(f.ground.size(), 20u);
  ASSERT_EQ(f.ground.visible_regions.size(), 1u);
  for (const auto& g : f.ground.points) {
    EXPECT_LT(nearestFeature(field, truth.transform(g.p_robot)).distance_m, 0.05);
    EXPECT_LT(std::abs(std::atan2(g.p_robot.y(), g.p_robot.x())),
              config.view.half_angle_rad + 0.02);
    EXPECT_LT(g.p_robot.norm(), config.view.max_range_m + 0.05);
  }
  // Deterministic for a seed, different for another.
  const SyntheticFrame again = generateFrame(field, truth, config);
  ASSERT_EQ(again.ground.size(), f.ground.size());
  EXPECT_EQ(again.ground.points[3].p_robot, f.ground.points[3].p_robot);
  config.seed = 2;
  EXPECT_NE(generateFrame(field, truth, config).ground.points[3].p_robot,
            f.ground.points[3].p_robot);
}

TEST(Synthetic, VisibleRegionIsClippedToTheCarpetAndShadowed) {
  const FieldModel field = makeStandardField("spl");
  // At the corner looking out of the field: most of the wedge is beyond the carpet.
  const Pose2 truth(4.4, 2.9, 0.785);
  SyntheticConfig config;
  config.occluders = 1;
  const SyntheticFrame f = generateFrame(field, truth, config);
  ASSERT_EQ(f.ground.visible_regions.size(), 1u);
  for (const auto& v : f.ground.visible_regions[0]) {
    const Eigen::Vector2d p = truth.transform(v);
    EXPECT_LE(std::abs(p.x()), field.outerHalfLength() + 1e-6);
    EXPECT_LE(std::abs(p.y()), field.outerHalfWidth() + 1e-6);
  }
  // A shadow: the region does not contain the point right behind an occluder.
  const Occluder o{Eigen::Vector2d(2.0, 0.0), 0.3};
  const GroundPolygon big = {{-20, -20}, {20, -20}, {20, 20}, {-20, 20}};
  const GroundPolygon region = visibleRegion(0.5, 0.4, 4.5, {o}, big);
  EXPECT_TRUE(insidePolygon(region, {1.5, 0.0}));
  EXPECT_FALSE(insidePolygon(region, {3.0, 0.0}));
  EXPECT_TRUE(insidePolygon(region, {3.0, 1.2}));
}

TEST(Synthetic, DirectionClassesFollowDesignMetrics) {
  const FieldModel field = makeStandardField("spl");
  SyntheticConfig config;
  config.view = viewModel("nao-top");
  // Facing the corner: two directions.
  EXPECT_TRUE(hasTwoDirections(generateFrame(field, Pose2(3.0, 1.8, 0.6), config)));
  // Facing the left touch line from close by, mid-way between other lines: parallel only.
  config.view.max_range_m = 1.5;
  const SyntheticFrame touch = generateFrame(field, Pose2(-1.5, 2.3, M_PI / 2), config);
  EXPECT_FALSE(hasTwoDirections(touch));
  EXPECT_TRUE(hasOnlyParallelLines(touch));
}

TEST(GridSearch, FindsACornerViewAmongItsOptima) {
  const FieldModel field = makeStandardField("spl");
  GridSearchLocalizer search(field);
  const Pose2 truth(2.9, 1.7, 0.55);
  SyntheticConfig config;
  config.view = viewModel("kid-wide");
  const auto optima = search.locate(generateFrame(field, truth, config).ground);
  ASSERT_FALSE(optima.empty());
  EXPECT_LE(optima.size(), 12u);
  bool found = false;
  for (const auto& o : optima) {
    for (const Pose2& t : {truth, Pose2(-truth.x, -truth.y, truth.theta + M_PI)}) {
      found |= (o.field_T_robot.translation() - t.translation()).norm() < 0.05 &&
               std::abs(angleDifference(o.field_T_robot.theta, t.theta)) < 0.02;
    }
  }
  EXPECT_TRUE(found);
  for (std::size_t k = 1; k < optima.size(); ++k) EXPECT_LE(optima[k].score, optima[k - 1].score);
  EXPECT_TRUE(search.locate(GroundPoints{}).empty());
}

}  // namespace
}  // namespace houghloc
