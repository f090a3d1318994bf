// The Localizer facade (issues 7 and 8): hints, falls, bad input, determinism.
#include "localization/localizer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "field_models/standard_fields.h"
#include "tests/localization/localizer_test_support.h"

namespace houghloc {
namespace {

using testing::correctPose;
using testing::estimateCorrect;
using testing::estimateFinite;
using testing::gaussianAt;
using testing::hint;
using testing::uprightCamera;

class LocalizerTest : public ::testing::Test {
 protected:
  LocalizerTest() : field_(makeStandardField("spl")), localizer_(field_) {}

  LocalizationEstimate run(const testing::ScenarioFrame& f) {
    return localizer_.process(f.t_us, f.odometry, {uprightCamera()}, f.points);
  }

  FieldModel field_;
  Localizer localizer_;
};

TEST_F(LocalizerTest, ResetToIsImmediateAndTrackedWithoutFlips) {
  const auto frames = testing::makeScenario(field_, testing::walkOn(field_, 240, 7));
  const Pose2 start = frames[0].field_T_robot;
  localizer_.applyHint(hint(HintKind::kResetTo, {gaussianAt(start)}));
  const LocalizationEstimate now = localizer_.estimate();
  ASSERT_EQ(now.hypotheses.size(), 1u);
  EXPECT_EQ(now.status, TrackerStatus::kTracking);
  EXPECT_NEAR(now.best()->mean.x, start.x, 1e-12);
  EXPECT_NEAR(now.best()->weight, 1.0, 1e-12);
  int correct = 0;
  for (const auto& f : frames) {
    const LocalizationEstimate e = run(f);
    ASSERT_TRUE(e.best());
    correct += correctPose(e.best()->mean, f.field_T_robot) ? 1 : 0;
    // Zero flips: the best stays with the truth (the start hint resolved the symmetry).
    EXPECT_LT((e.best()->mean.translation() - f.field_T_robot.translation()).norm(), 0.3);
  }
  EXPECT_GE(correct, static_cast<int>(frames.size()) - 3);
}

TEST_F(LocalizerTest, AddKeepsOldPosesAndAddsNewOnes) {
  localizer_.applyHint(hint(HintKind::kResetTo, {gaussianAt(Pose2(-1.0, 0.5, 0.2))}));
  localizer_.applyHint(hint(HintKind::kAdd, {gaussianAt(Pose2(2.0, -1.0, 1.0))}));
  const LocalizationEstimate e = localizer_.estimate();
  ASSERT_EQ(e.hypotheses.size(), 2u);
  EXPECT_NEAR(e.hypotheses[0].pose.weight + e.hypotheses[1].pose.weight, 1.0, 1e-12);
  // The one weight rule: share x belief, the new pose 3.4 m from the old one: belief = floor.
  const double share = localizer_.config().tracker.hint_add_share;
  const double added = share * localizer_.config().tracker.belief_floor;
  bool old_found = false, new_found = false;
  for (const EstimateHypothesis& h : e.hypotheses) {
    if (correctPose(h.pose.mean, Pose2(-1.0, 0.5, 0.2))) {
      old_found = true;
      EXPECT_NEAR(h.pose.weight, (1.0 - share) / (1.0 - share + added), 1e-9);
    }
    if (correctPose(h.pose.mean, Pose2(2.0, -1.0, 1.0))) {
      new_found = true;
      EXPECT_NEAR(h.pose.weight, added / (1.0 - share + added), 1e-9);
    }
  }
  EXPECT_TRUE(old_found && new_found);
}

TEST_F(LocalizerTest, OwnHalfMirrorsOpponentHalfAndMirrorFlipsAll) {
  localizer_.applyHint(hint(HintKind::kResetTo, {gaussianAt(Pose2(2.0, 1.0, 0.3), 0.6),
                                                 gaussianAt(Pose2(-1.5, -0.5, 1.0), 0.4)}));
  localizer_.applyHint(hint(HintKind::kOwnHalf));
  LocalizationEstimate e = localizer_.estimate();
  ASSERT_EQ(e.hypotheses.size(), 2u);
  EXPECT_TRUE(correctPose(e.hypotheses[0].pose.mean, Pose2(-2.0, -1.0, 0.3 + M_PI)));
  EXPECT_TRUE(correctPose(e.hypotheses[1].pose.mean, Pose2(-1.5, -0.5, 1.0)));
  localizer_.applyHint(hint(HintKind::kMirror));
  e = localizer_.estimate();
  ASSERT_EQ(e.hypotheses.size(), 2u);
  EXPECT_TRUE(correctPose(e.hypotheses[0].pose.mean, Pose2(2.0, 1.0, 0.3)));
  EXPECT_TRUE(correctPose(e.hypotheses[1].pose.mean, Pose2(1.5, 0.5, 1.0 + M_PI)));
  EXPECT_NEAR(e.hypotheses[0].pose.weight, 0.6, 1e-9);
}

TEST_F(LocalizerTest, UnknownForgetsAndRelocalisesGlobally) {
  const auto frames = testing::makeScenario(field_, testing::walkOn(field_, 60, 9));
  localizer_.applyHint(hint(HintKind::kResetTo, {gaussianAt(Pose2(3.0, 2.0, -1.0))}));  // wrong
  localizer_.applyHint(hint(HintKind::kUnknown));
  EXPECT_TRUE(localizer_.estimate().hypotheses.empty());
  EXPECT_EQ(localizer_.estimate().status, TrackerStatus::kInitializing);
  const LocalizationEstimate first = run(frames[0]);
  EXPECT_TRUE(first.global_ran);
  int correct_at = -1;
  for (size_t k = 1; k < frames.size() && correct_at < 0; ++k) {
    if (estimateCorrect(run(frames[k]), frames[k].field_T_robot)) correct_at = k;
  }
  EXPECT_GE(correct_at, 0);
  EXPECT_LE(correct_at, 10);
}

/// A robot lying on its back for 2 s: its camera 0.1 m above the ground looking up, garbage
/// odometry and random points. It gets up 0.6 rad turned where it fell and walks on.
TEST_F(LocalizerTest, FallThenRelocalises) {
  testing::ScenarioConfig config = testing::walkOn(field_, 330, 13);
  const int fall = 120, up = 180;
  std::vector<testing::ScenarioFrame> walk = testing::makeScenario(field_, config);
  const Pose2 lying = walk[fall].field_T_robot;
  config.kidnap_frame = up;
  config.kidnap_to = lying * Pose2(0.0, 0.0, 0.6);
  const auto after = testing::makeScenario(field_, config);
  localizer_.applyHint(hint(HintKind::kResetTo, {gaussianAt(walk[0].field_T_robot)}));
  Pose3 fallen_camera;
  fallen_camera.z = 0.1;
  fallen_camera.pitch = -1.4;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> garbage(-5.0, 5.0);
  int recovered_at = -1;
  for (int k = 0; k < config.frames; ++k) {
    const bool lying_down = k >= fall && k < up;
    const testing::ScenarioFrame& f = k < up ? walk[k] : after[k];
    LocalizationEstimate e;
    if (lying_down) {
      GroundPoints points;
      for (int i = 0; i < 50; ++i) points.points.push_back({{garbage(rng), garbage(rng)}});
      e = localizer_.process(f.t_us, Pose2(garbage(rng), garbage(rng), garbage(rng)),
                             {fallen_camera}, points);
      EXPECT_TRUE(e.fallen);
      EXPECT_EQ(e.status, TrackerStatus::kLost);
      EXPECT_FALSE(e.global_ran);
    } else {
      e = run(f);
      EXPECT_FALSE(e.fallen);
      if (k < fall) {
        EXPECT_TRUE(correctPose(e.best()->mean, f.field_T_robot)) << k;
      }
      if (k >= up && recovered_at < 0 && estimateCorrect(e, f.field_T_robot)) recovered_at = k;
    }
    ASSERT_TRUE(estimateFinite(e)) << k;
  }
  ASSERT_GE(recovered_at, up);
  RecordProperty("recovered_after_frames", recovered_at - up);
  EXPECT_LE(recovered_at - up, 30);
  EXPECT_TRUE(estimateCorrect(localizer_.estimate(), after.back().field_T_robot));
}

}  // namespace
}  // namespace houghloc
