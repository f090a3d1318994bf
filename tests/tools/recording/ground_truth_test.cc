#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "field_models/angles.h"
#include "tools/recording/recording.h"

namespace houghloc {
namespace {

const std::vector<GroundTruthRecord> kTruth = {
    {1'000'000, Pose2(0.0, 0.0, 0.0)},
    {1'010'000, Pose2(1.0, -2.0, 0.5)},
    {1'020'000, Pose2(2.0, -2.0, 3.0)},
    {1'030'000, Pose2(2.0, -1.0, -3.0)},  // crosses +-pi from the row before
    {2'000'000, Pose2(5.0, 5.0, 1.0)},    // after a gap of almost a second
};

TEST(GroundTruthAt, ExactRowsAreReturnedUnchanged) {
  for (const GroundTruthRecord& r : kTruth) {
    const auto pose = groundTruthAt(kTruth, r.t_us);
    ASSERT_TRUE(pose);
    EXPECT_EQ(pose->x, r.field_T_robot.x);
    EXPECT_EQ(pose->theta, r.field_T_robot.theta);
  }
}

TEST(GroundTruthAt, InterpolatesLinearlyAndAnglesOnTheCircle) {
  const auto quarter = groundTruthAt(kTruth, 1'002'500);
  ASSERT_TRUE(quarter);
  EXPECT_NEAR(quarter->x, 0.25, 1e-12);
  EXPECT_NEAR(quarter->y, -0.5, 1e-12);
  EXPECT_NEAR(quarter->theta, 0.125, 1e-12);
  // From 3.0 to -3.0 the short way round passes pi: half way is pi, not 0.
  const auto across = groundTruthAt(kTruth, 1'025'000);
  ASSERT_TRUE(across);
  EXPECT_NEAR(std::abs(across->theta), kPi, 1e-12);
  EXPECT_NEAR(across->y, -1.5, 1e-12);
  const auto late = groundTruthAt(kTruth, 1'027'500);
  ASSERT_TRUE(late);
  EXPECT_NEAR(late->theta, -kPi + (2.0 * kPi - 6.0) * 0.25, 1e-12);
}

TEST(GroundTruthAt, ToleranceAndGaps) {
  // Before the first and after the last row: the nearest row within +-20 ms.
  ASSERT_TRUE(groundTruthAt(kTruth, 980'000));
  EXPECT_EQ(groundTruthAt(kTruth, 980'000)->x, 0.0);
  EXPECT_FALSE(groundTruthAt(kTruth, 979'999));
  EXPECT_EQ(groundTruthAt(kTruth, 2'020'000)->x, 5.0);
  EXPECT_FALSE(groundTruthAt(kTruth, 2'020'001));
  // Inside the gap: never bridged; near either end the nearest row is used.
  EXPECT_EQ(groundTruthAt(kTruth, 1'049'000)->x, 2.0);
  EXPECT_FALSE(groundTruthAt(kTruth, 1'500'000));
  EXPECT_EQ(groundTruthAt(kTruth, 1'985'000)->y, 5.0);
  // A tighter tolerance.
  EXPECT_FALSE(groundTruthAt(kTruth, 1'005'000, 1000));
  EXPECT_TRUE(groundTruthAt(kTruth, 1'009'500, 1000));
  EXPECT_FALSE(groundTruthAt({}, 0));
  EXPECT_FALSE(groundTruthAt(kTruth, std::numeric_limits<std::int64_t>::max()));
  EXPECT_FALSE(groundTruthAt(kTruth, std::numeric_limits<std::int64_t>::min()));
}

}  // namespace
}  // namespace houghloc
