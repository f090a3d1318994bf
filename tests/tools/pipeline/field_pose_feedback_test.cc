#include "tools/pipeline/field_pose_feedback.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

namespace houghloc {
namespace {

LocalizationEstimate estimateAt(const Pose2& pose, TrackerStatus status) {
  LocalizationEstimate estimate;
  estimate.status = status;
  EstimateHypothesis h;
  h.pose.mean = pose;
  estimate.hypotheses.push_back(h);
  return estimate;
}

TEST(FieldPoseFeedback, PredictsTheLaggedEstimateWithOdometry) {
  FieldPoseFeedback feedback(10, 3);
  // Frames before first_frame + lag have no estimate to go by.
  EXPECT_FALSE(feedback.guessFor(12, Pose2()));
  feedback.publish(10, Pose2(5.0, 1.0, 0.5 * M_PI),
                   estimateAt(Pose2(-1.0, 2.0, 0.0), TrackerStatus::kTracking));
  feedback.consumed(10);
  // Odometry: 0.2 m forward in its own frame (here along its y) since frame 10, and a turn.
  const auto guess = feedback.guessFor(13, Pose2(5.0, 1.2, 0.5 * M_PI + 0.1));
  ASSERT_TRUE(guess);
  EXPECT_NEAR(guess->x, -0.8, 1e-12);
  EXPECT_NEAR(guess->y, 2.0, 1e-12);
  EXPECT_NEAR(guess->theta, 0.1, 1e-12);
  // Without odometry, the estimate as it was.
  const double nan = std::nan("");
  const auto unmoved = feedback.guessFor(13, Pose2(nan, nan, nan));
  ASSERT_TRUE(unmoved);
  EXPECT_NEAR(unmoved->x, -1.0, 1e-12);
}

TEST(FieldPoseFeedback, GivesNothingWhileTheTrackerIsLost) {
  FieldPoseFeedback feedback(0, 3);
  feedback.publish(0, Pose2(), estimateAt(Pose2(1.0, 1.0, 0.0), TrackerStatus::kLost));
  feedback.consumed(0);
  feedback.publish(1, Pose2(), LocalizationEstimate{});  // no hypothesis at all
  feedback.consumed(1);
  EXPECT_FALSE(feedback.guessFor(3, Pose2()));
  EXPECT_FALSE(feedback.guessFor(4, Pose2()));
}

TEST(FieldPoseFeedback, WaitsForTheLaggedFrameAndStopsOnAbort) {
  FieldPoseFeedback feedback(0, 3);
  std::optional<Pose2> guess = Pose2(9.0, 9.0, 0.0);
  std::thread vision([&] { guess = feedback.guessFor(5, Pose2()); });
  feedback.publish(2, Pose2(), estimateAt(Pose2(1.0, 0.0, 0.0), TrackerStatus::kAmbiguous));
  feedback.consumed(2);
  vision.join();
  ASSERT_TRUE(guess);
  EXPECT_NEAR(guess->x, 1.0, 1e-12);
  std::thread waiting([&] { guess = feedback.guessFor(9, Pose2()); });
  feedback.abort();
  waiting.join();
  EXPECT_FALSE(guess);
}

}  // namespace
}  // namespace houghloc
