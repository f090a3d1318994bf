#include "field_models/line_features.h"

#include <gtest/gtest.h>

#include <cmath>

namespace houghloc {
namespace {

constexpr double kTol = 1e-12;

TEST(Segment2Test, ClosestPointProjectsAndClamps) {
  const Segment2 s{{1.0, 1.0}, {4.0, 1.0}};
  EXPECT_LT((s.closestPoint({2.5, 3.0}) - Eigen::Vector2d(2.5, 1.0)).norm(), kTol);
  EXPECT_LT((s.closestPoint({0.0, 0.0}) - Eigen::Vector2d(1.0, 1.0)).norm(), kTol);
  EXPECT_LT((s.closestPoint({7.0, -3.0}) - Eigen::Vector2d(4.0, 1.0)).norm(), kTol);
  EXPECT_NEAR(s.distanceTo({7.0, 5.0}), 5.0, kTol);  // 3-4-5 from the end (4, 1)
  EXPECT_NEAR(s.length(), 3.0, kTol);
  EXPECT_LT((s.direction() - Eigen::Vector2d(1.0, 0.0)).norm(), kTol);

  const Segment2 diagonal{{0.0, 0.0}, {2.0, 2.0}};
  EXPECT_NEAR(diagonal.distanceTo({2.0, 0.0}), std::sqrt(2.0), kTol);
  EXPECT_LT((diagonal.closestPoint({2.0, 0.0}) - Eigen::Vector2d(1.0, 1.0)).norm(), kTol);

  const Segment2 point{{1.0, 2.0}, {1.0, 2.0}};
  EXPECT_NEAR(point.distanceTo({4.0, 6.0}), 5.0, kTol);
  EXPECT_EQ(point.direction(), Eigen::Vector2d::Zero());
}

TEST(Arc2Test, ClosestPointOnAndOffTheArc) {
  // Upper half circle of radius 2 around (1, 0).
  const Arc2 arc{{1.0, 0.0}, 2.0, 0.0, M_PI};
  EXPECT_LT((arc.closestPoint({1.0, 5.0}) - Eigen::Vector2d(1.0, 2.0)).norm(), kTol);
  EXPECT_NEAR(arc.distanceTo({4.0, 0.0}), 1.0, kTol);                   // on the start ray
  EXPECT_NEAR(arc.distanceTo({2.0, 1.0}), 2.0 - std::sqrt(2.0), kTol);  // inside
  // Below the centre the arc's nearest part is an end point, (3, 0) or (-1, 0).
  EXPECT_LT((arc.closestPoint({2.5, -1.0}) - Eigen::Vector2d(3.0, 0.0)).norm(), kTol);
  EXPECT_LT((arc.closestPoint({-0.5, -1.0}) - Eigen::Vector2d(-1.0, 0.0)).norm(), kTol);
  EXPECT_NEAR(arc.length(), 2.0 * M_PI, kTol);
  // The centre is equally far from every arc point: distance is the radius.
  EXPECT_NEAR(arc.distanceTo({1.0, 0.0}), 2.0, kTol);
}

TEST(Arc2Test, ContainsAngleAcrossTheWrap) {
  const Arc2 arc{{0.0, 0.0}, 1.0, 3.0, 1.0};  // from 3 rad over pi to 4 rad = -2.28 rad
  EXPECT_TRUE(arc.containsAngle(3.1));
  EXPECT_TRUE(arc.containsAngle(-3.1));
  EXPECT_TRUE(arc.containsAngle(-2.3));  // 3.98 rad
  EXPECT_FALSE(arc.containsAngle(2.9));
  EXPECT_FALSE(arc.containsAngle(-2.2));
  const Arc2 circle{{0.0, 0.0}, 0.75, 0.0, 2.0 * M_PI};
  EXPECT_TRUE(circle.isFullCircle());
  EXPECT_NEAR(circle.distanceTo({0.0, -2.0}), 1.25, kTol);
}

TEST(MarkTest, DistanceToCrossAndDot) {
  const Mark cross{{3.2, 0.0}, 0.1, MarkShape::kCross};
  EXPECT_NEAR(cross.distanceTo({3.2, 0.02}), 0.0, kTol);    // on the bar along y
  EXPECT_NEAR(cross.distanceTo({3.22, 0.02}), 0.02, kTol);  // between the bars
  EXPECT_NEAR(cross.distanceTo({3.2, 0.35}), 0.3, kTol);    // beyond the bar's end
  const Mark dot{{0.0, 0.0}, 0.2, MarkShape::kDot};
  EXPECT_NEAR(dot.distanceTo({0.05, 0.0}), 0.0, kTol);
  EXPECT_NEAR(dot.distanceTo({0.3, 0.4}), 0.4, kTol);
}

}  // namespace
}  // namespace houghloc
