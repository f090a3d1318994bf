// The publication order of houghloc-play: by time, inputs before the image they belong to.
#include "tools/play/play_schedule.h"

#include <gtest/gtest.h>

namespace houghloc {
namespace {

TEST(PlaySchedule, OrdersByTimeWithInputsBeforeTheImage) {
  Recording rec;
  for (int i = 0; i < 3; ++i) {
    FrameRecord f;
    f.t_us = i * 33'000;
    rec.frames.push_back(f);
  }
  rec.hints.push_back({33'000, "OWN_HALF", std::nullopt, 0, 0, 0});
  rec.ground_truth.push_back({10'000, Pose2()});
  rec.ground_truth.push_back({33'000, Pose2()});
  const std::vector<PlayEvent> events = buildSchedule(rec, 1);
  ASSERT_EQ(events.size(), 12u);
  using K = PlayEvent::Kind;
  const std::vector<K> expected = {K::kOdometry,    K::kCameraPose, K::kImage,      K::kGroundTruth,
                                   K::kHint,        K::kOdometry,   K::kCameraPose, K::kImage,
                                   K::kGroundTruth, K::kOdometry,   K::kCameraPose, K::kImage};
  for (std::size_t i = 0; i < events.size(); ++i) EXPECT_EQ(events[i].kind, expected[i]) << i;
  EXPECT_EQ(events[7].index, 1u);
  EXPECT_EQ(events[8].index, 1u);  // the second ground-truth row
  EXPECT_EQ(events[11].t_us, 66'000);
}

TEST(PlaySchedule, RowWithoutOdometryPublishesNoOdometry) {
  Recording rec;
  for (int i = 0; i < 3; ++i) {
    FrameRecord f;
    f.t_us = i * 33'000;
    if (i == 1) f.odometry = std::nullopt;  // empty odom_* fields
    rec.frames.push_back(f);
  }
  const std::vector<PlayEvent> events = buildSchedule(rec, 0);
  ASSERT_EQ(events.size(), 8u);
  using K = PlayEvent::Kind;
  const std::vector<K> expected = {K::kOdometry, K::kCameraPose, K::kImage,      K::kCameraPose,
                                   K::kImage,    K::kOdometry,   K::kCameraPose, K::kImage};
  for (std::size_t i = 0; i < events.size(); ++i) EXPECT_EQ(events[i].kind, expected[i]) << i;
  EXPECT_EQ(events[3].index, 1u);
  EXPECT_EQ(events[5].index, 2u);
}

}  // namespace
}  // namespace houghloc
