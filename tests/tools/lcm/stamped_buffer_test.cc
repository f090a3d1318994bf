// StampedBuffer: interpolation at an image's utime, the 50 ms rule, restarts, angles across pi.
#include "tools/lcm/stamped_buffer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tools/lcm/drop_counters.h"

namespace houghloc {
namespace {

TEST(StampedBuffer, InterpolatesBetweenSamples) {
  StampedBuffer<Pose2> buffer;
  buffer.push(1'000'000, Pose2(0.0, 0.0, 0.0));
  buffer.push(1'020'000, Pose2(0.2, -0.1, 0.1));
  const auto mid = buffer.at(1'005'000, 50'000);
  ASSERT_TRUE(mid.has_value());
  EXPECT_NEAR(mid->x, 0.05, 1e-12);
  EXPECT_NEAR(mid->y, -0.025, 1e-12);
  EXPECT_NEAR(mid->theta, 0.025, 1e-12);
  EXPECT_NEAR(buffer.at(1'020'000, 0)->x, 0.2, 1e-12);  // exact sample
}

TEST(StampedBuffer, AnglesInterpolateTheShortWay) {
  StampedBuffer<Pose2> buffer;
  buffer.push(0, Pose2(0.0, 0.0, M_PI - 0.1));
  buffer.push(10, Pose2(0.0, 0.0, -M_PI + 0.1));
  EXPECT_NEAR(std::abs(buffer.at(5, 50)->theta), M_PI, 1e-12);
  StampedBuffer<Pose3> cams;
  Pose3 a, b;
  a.yaw = 3.1;
  b.yaw = -3.1;
  a.pitch = 0.2;
  b.pitch = 0.4;
  cams.push(0, a);
  cams.push(10, b);
  const Pose3 mid = *cams.at(5, 50);
  EXPECT_NEAR(std::abs(mid.yaw), M_PI, 1e-12);
  EXPECT_NEAR(mid.pitch, 0.3, 1e-12);
}

TEST(StampedBuffer, FiftyMillisecondRule) {
  StampedBuffer<Pose3> buffer;
  EXPECT_FALSE(buffer.at(0, 50'000).has_value());  // empty
  Pose3 p;
  p.z = 0.5;
  buffer.push(1'000'000, p);
  EXPECT_TRUE(buffer.at(1'050'000, 50'000).has_value());   // after the last, within 50 ms
  EXPECT_FALSE(buffer.at(1'050'001, 50'000).has_value());  // 50 ms + 1 us
  EXPECT_FALSE(buffer.at(949'999, 50'000).has_value());    // before the first
  buffer.push(1'200'000, p);                               // a 200 ms gap
  EXPECT_TRUE(buffer.at(1'040'000, 50'000).has_value());
  EXPECT_FALSE(buffer.at(1'100'000, 50'000).has_value());  // 100 ms from either side
}

TEST(StampedBuffer, ForgetsOldSamplesAndRestarts) {
  StampedBuffer<Pose2> buffer(100'000);
  for (int i = 0; i <= 20; ++i) buffer.push(i * 10'000, Pose2(i, 0.0, 0.0));
  EXPECT_FALSE(buffer.at(50'000, 20'000).has_value());  // older than 100 ms before the newest
  EXPECT_NEAR(buffer.at(150'000, 0)->x, 15.0, 1e-12);
  buffer.push(5'000, Pose2(-1.0, 0.0, 0.0));  // clock went back: a restarted publisher
  EXPECT_EQ(*buffer.newest(), 5'000);
  EXPECT_FALSE(buffer.at(150'000, 20'000).has_value());
  EXPECT_NEAR(buffer.at(5'000, 0)->x, -1.0, 1e-12);
}

TEST(DropCounters, CountsPerReason) {
  DropCounters drops;
  drops.add(DropReason::kOldImage);
  drops.add(DropReason::kMalformed);
  drops.add(DropReason::kMalformed);
  drops.add(DropReason::kQueueFull);
  localizer_status_t status{};
  drops.fill(status);
  EXPECT_EQ(status.dropped_old_image, 1);
  EXPECT_EQ(status.dropped_malformed, 2);
  EXPECT_EQ(status.dropped_queue_full, 1);
  EXPECT_EQ(status.dropped_no_camera_pose, 0);
  EXPECT_EQ(drops.total(), 4);
  EXPECT_STREQ(dropReasonName(DropReason::kNoCameraPose), "no camera pose");
}

}  // namespace
}  // namespace houghloc
