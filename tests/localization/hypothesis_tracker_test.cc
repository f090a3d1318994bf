#include "localization/hypothesis_tracker.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "field_models/standard_fields.h"
#include "tests/localization/localizer_test_support.h"
#include "tests/localization/tracking_scenario.h"

namespace houghloc {
namespace {

using testing::gaussianAt;
using testing::hint;

void expectFinite(const HypothesisTracker& tracker) {
  for (const TrackedHypothesis& h : tracker.hypotheses()) {
    EXPECT_TRUE(h.pose.isFinite());
    EXPECT_GE(h.pose.covariance.diagonal().minCoeff(), 0.0);
  }
}

class HypothesisTrackerTest : public ::testing::Test {
 protected:
  FieldModel field_ = makeStandardField("spl");
  std::shared_ptr<const FeatureIndex> index_ = std::make_shared<const FeatureIndex>(field_);
  HypothesisTracker tracker_{index_, TrackerConfig{}};
};

TEST_F(HypothesisTrackerTest, StartsInitializingAndAsksForGlobalHypotheses) {
  EXPECT_EQ(tracker_.status(), TrackerStatus::kInitializing);
  EXPECT_TRUE(tracker_.needsGlobalHypotheses());
  tracker_.update(0, Pose2(), GroundPoints{});
  EXPECT_TRUE(tracker_.hypotheses().empty());
}

TEST_F(HypothesisTrackerTest, ResetAddMirrorOwnHalfAndUnknownHints) {
  tracker_.applyHint(hint(HintKind::kResetTo, {gaussianAt(Pose2(2.0, 1.0, 0.3), 1.0, 0.1, 0.1)}));
  ASSERT_EQ(tracker_.hypotheses().size(), 1u);
  EXPECT_NEAR(tracker_.hypotheses()[0].pose.mean.x, 2.0, 1e-12);
  EXPECT_NEAR(tracker_.hypotheses()[0].pose.weight, 1.0, 1e-12);
  EXPECT_FALSE(tracker_.needsGlobalHypotheses());

  tracker_.applyHint(hint(HintKind::kAdd, {gaussianAt(Pose2(-1.0, 0.0, 0.0), 1.0, 0.1, 0.1)}));
  ASSERT_EQ(tracker_.hypotheses().size(), 2u);
  // The one weight rule: hint_add_share x belief; (-1, 0, 0) is 3.2 m from the only hypothesis,
  // so its belief is the floor. Normalised against the old pose's 1 - share:
  const double share = tracker_.config().hint_add_share, floor = tracker_.config().belief_floor;
  EXPECT_NEAR(tracker_.hypotheses()[1].pose.weight, share * floor / (1.0 - share + share * floor),
              1e-12);

  // OWN_HALF: (2, 1, 0.3) lies in the opponent half; its mirror (-2, -1, 0.3 + pi) replaces it.
  tracker_.applyHint(hint(HintKind::kOwnHalf));
  ASSERT_EQ(tracker_.hypotheses().size(), 2u);
  for (const auto& h : tracker_.hypotheses()) EXPECT_LE(h.pose.mean.x, 0.0);
  bool found = false;
  for (const auto& h : tracker_.hypotheses()) {
    found |= std::abs(h.pose.mean.x + 2.0) < 1e-9 && std::abs(h.pose.mean.y + 1.0) < 1e-9 &&
             std::abs(angleDifference(h.pose.mean.theta, 0.3 + M_PI)) < 1e-9;
  }
  EXPECT_TRUE(found);

  tracker_.applyHint(hint(HintKind::kMirror));
  for (const auto& h : tracker_.hypotheses()) EXPECT_GE(h.pose.mean.x, 0.0);

  tracker_.applyHint(hint(HintKind::kUnknown));
  EXPECT_TRUE(tracker_.hypotheses().empty());
  EXPECT_TRUE(tracker_.needsGlobalHypotheses());
  EXPECT_EQ(tracker_.status(), TrackerStatus::kInitializing);
}

TEST_F(HypothesisTrackerTest, MirrorPairStaysAmbiguousUntilOwnHalfHint) {
  const Pose2 truth(-2.0, 1.0, 0.4);
  tracker_.applyHint(hint(HintKind::kResetTo, {gaussianAt(truth, 1.0, 0.1, 0.1),
                                               mirrored(gaussianAt(truth, 1.0, 0.1, 0.1))}));
  testing::ScenarioConfig view;
  for (int k = 0; k < 10; ++k) {
    tracker_.update(k * 33000, Pose2(), testing::samplePoints(field_, truth, 0.0, view, k));
  }
  ASSERT_EQ(tracker_.hypotheses().size(), 2u);
  EXPECT_TRUE(tracker_.topHypothesesMirrorAmbiguous());
  EXPECT_EQ(tracker_.status(), TrackerStatus::kAmbiguous);
  tracker_.applyHint(hint(HintKind::kOwnHalf));
  ASSERT_EQ(tracker_.hypotheses().size(), 1u);
  EXPECT_EQ(tracker_.status(), TrackerStatus::kTracking);
  EXPECT_NEAR(tracker_.hypotheses()[0].pose.mean.x, truth.x, 0.03);
  EXPECT_NEAR(tracker_.hypotheses()[0].pose.mean.y, truth.y, 0.03);
}

TEST_F(HypothesisTrackerTest, WrongHypothesisLosesWeightAndIsPruned) {
  const Pose2 truth(-2.0, 1.0, 0.4);
  tracker_.applyHint(hint(HintKind::kResetTo, {gaussianAt(truth, 1.0, 0.1, 0.1),
                                               gaussianAt(Pose2(1.0, -1.5, 2.0), 1.0, 0.1, 0.1)}));
  testing::ScenarioConfig view;
  for (int k = 0; k < 5; ++k) {
    tracker_.update(k * 33000, Pose2(), testing::samplePoints(field_, truth, 0.0, view, k));
  }
  ASSERT_EQ(tracker_.hypotheses().size(), 1u);
  EXPECT_NEAR(tracker_.hypotheses()[0].pose.mean.x, truth.x, 0.03);
  EXPECT_EQ(tracker_.status(), TrackerStatus::kTracking);
}

TEST_F(HypothesisTrackerTest, OdometryJumpNanAndBackwardTimeNeverGiveNan) {
  tracker_.applyHint(
      hint(HintKind::kResetTo, {gaussianAt(Pose2(-1.0, 0.0, 0.0), 1.0, 0.02, 0.02)}));
  tracker_.update(0, Pose2(0.0, 0.0, 0.0), GroundPoints{});
  tracker_.update(33000, Pose2(0.01, 0.0, 0.0), GroundPoints{});
  EXPECT_NEAR(tracker_.hypotheses()[0].pose.mean.x, -0.99, 1e-9);
  const double var_before = tracker_.hypotheses()[0].pose.covariance(0, 0);
  tracker_.update(66000, Pose2(1e6, -3e5, 2.0), GroundPoints{});  // jump: not applied
  EXPECT_TRUE(tracker_.lastStats().odometry_jump);
  EXPECT_NEAR(tracker_.hypotheses()[0].pose.mean.x, -0.99, 1e-9);
  EXPECT_GT(tracker_.hypotheses()[0].pose.covariance(0, 0), var_before);
  EXPECT_TRUE(tracker_.needsGlobalHypotheses());
  const double nan = std::nan("");
  tracker_.update(99000, Pose2(nan, nan, nan), GroundPoints{});
  tracker_.update(-5000000, Pose2(1e6, -3e5, 2.0), GroundPoints{});  // time backwards
  EXPECT_TRUE(tracker_.lastStats().time_backwards);
  tracker_.update(std::numeric_limits<std::int64_t>::max() / 2, std::nullopt, GroundPoints{});
  GroundPoints bad;
  bad.points.push_back(GroundPoint{Eigen::Vector2d(nan, 1.0)});
  bad.points.push_back(GroundPoint{Eigen::Vector2d(1e300, -1e300)});
  tracker_.update(std::numeric_limits<std::int64_t>::max() / 2 + 1, Pose2(), bad);
  ASSERT_FALSE(tracker_.hypotheses().empty());
  expectFinite(tracker_);
  EXPECT_EQ(tracker_.status(), TrackerStatus::kLost);  // covariance blew up with the clock gap
}

TEST_F(HypothesisTrackerTest, TenSecondsWithoutPoints) {
  testing::ScenarioConfig config;
  config.frames = 330;
  const auto frames = testing::makeScenario(field_, config);
  const GaussianPose start = gaussianAt(frames[0].field_T_robot, 1.0, 0.02, 0.02);
  // With odometry: uncertainty grows with the distance walked, the tracker keeps going.
  tracker_.applyHint(hint(HintKind::kResetTo, {start}));
  for (const auto& f : frames) tracker_.update(f.t_us, f.odometry, GroundPoints{});
  expectFinite(tracker_);
  EXPECT_NEAR(tracker_.lastStats().seconds_without_points, 10.97, 0.01);
  const Eigen::Matrix3d& cov = tracker_.hypotheses()[0].pose.covariance;
  EXPECT_GT(cov(0, 0) + cov(1, 1), 0.05 * 0.05);
  const double error =
      (tracker_.hypotheses()[0].pose.mean.translation() - frames.back().field_T_robot.translation())
          .norm();
  EXPECT_LT(error, 3.0 * std::sqrt(cov(0, 0) + cov(1, 1)));  // honest covariance
  // Without odometry either: LOST and asking for global hypotheses.
  HypothesisTracker blind(index_, TrackerConfig{});
  blind.applyHint(hint(HintKind::kResetTo, {start}));
  for (const auto& f : frames) blind.update(f.t_us, std::nullopt, GroundPoints{});
  expectFinite(blind);
  EXPECT_EQ(blind.status(), TrackerStatus::kLost);
  EXPECT_TRUE(blind.needsGlobalHypotheses());
}

TEST_F(HypothesisTrackerTest, AsksForGlobalAtLowRateAndWhenObservationsDisagree) {
  const Pose2 truth(-2.0, 1.0, 0.4);
  tracker_.applyHint(hint(HintKind::kResetTo, {gaussianAt(truth, 1.0, 0.02, 0.02)}));
  testing::ScenarioConfig view;
  int k = 0;
  for (; k < 30; ++k) {
    tracker_.update(k * 33333, Pose2(), testing::samplePoints(field_, truth, 0.0, view, k));
    if (k == 0) {  // the hint is checked by one global run on the first frame with points
      EXPECT_TRUE(tracker_.needsGlobalHypotheses());
      tracker_.injectHypotheses({gaussianAt(truth, 1.0, 0.1, 0.1)});
    }
    EXPECT_FALSE(tracker_.needsGlobalHypotheses()) << k;
  }
  for (; k < 95; ++k) {
    tracker_.update(k * 33333, Pose2(), testing::samplePoints(field_, truth, 0.0, view, k));
  }
  EXPECT_TRUE(tracker_.needsGlobalHypotheses());  // periodic_global_s = 3 s passed
  tracker_.injectHypotheses({gaussianAt(truth, 1.0, 0.1, 0.1)});
  EXPECT_FALSE(tracker_.needsGlobalHypotheses());
  // Kidnap: the same odometry, a different view. Disagreement for disagree_frames frames.
  const Pose2 elsewhere(2.5, -1.5, 2.5);
  for (int j = 0; j < 5; ++j, ++k) {
    tracker_.update(k * 33333, Pose2(), testing::samplePoints(field_, elsewhere, 0.0, view, k));
  }
  EXPECT_TRUE(tracker_.needsGlobalHypotheses());
  EXPECT_EQ(tracker_.status(), TrackerStatus::kLost);
  expectFinite(tracker_);
}

// Kidnap where the old pose still explains about half of the new view (rendered SPL recording
// near the centre circle): the disagreement count never fires, the drop of the inlier share does.
TEST_F(HypothesisTrackerTest, SuddenDropOfInlierShareAsksForGlobalAtOnce) {
  const Pose2 truth(-2.0, 1.0, 0.4), elsewhere(2.5, -1.5, 2.5);
  testing::ScenarioConfig view;
  auto mixed = [&](int k) {  // the old view and 3/4 as many points of a new one
    GroundPoints points = testing::samplePoints(field_, truth, 0.0, view, k);
    const GroundPoints other = testing::samplePoints(field_, elsewhere, 0.0, view, 1000 + k);
    const size_t n = std::min(other.points.size(), points.points.size() * 3 / 4);
    points.points.insert(points.points.end(), other.points.begin(), other.points.begin() + n);
    return points;
  };
  TrackerConfig without_detector;
  without_detector.share_drop_alarm = 1e9;
  HypothesisTracker old_rules(index_, without_detector);
  for (HypothesisTracker* t : {&tracker_, &old_rules}) {
    t->applyHint(hint(HintKind::kResetTo, {gaussianAt(truth, 1.0, 0.02, 0.02)}));
    for (int k = 0; k < 30; ++k) {
      t->update(k * 33333, Pose2(), testing::samplePoints(field_, truth, 0.0, view, k));
      if (k == 0) {  // the hint's global check
        ASSERT_TRUE(t->needsGlobalHypotheses());
        t->injectHypotheses({gaussianAt(truth, 1.0, 0.1, 0.1)});
      }
      ASSERT_FALSE(t->needsGlobalHypotheses()) << k;
    }
  }
  int k = 30;
  for (; k < 34; ++k) {  // a third less explained: fires within four frames
    tracker_.update(k * 33333, Pose2(), mixed(k));
    old_rules.update(k * 33333, Pose2(), mixed(k));
  }
  const double share = tracker_.lastStats().best_inlier_share;
  EXPECT_GT(share, TrackerConfig{}.disagree_inlier_share);
  EXPECT_LT(share, 0.8);
  EXPECT_TRUE(tracker_.needsGlobalHypotheses());
  EXPECT_NE(tracker_.status(), TrackerStatus::kLost);  // not the disagreement count
  EXPECT_FALSE(old_rules.needsGlobalHypotheses());
  // A lasting change (say a robot in view that looks like lines): the expected share adapts and
  // the requests stop well within the low-rate period.
  int requests = 0, last_request = k;
  for (; k < 110; ++k) {
    if (tracker_.needsGlobalHypotheses()) {
      ++requests;
      last_request = k;
      tracker_.injectHypotheses({gaussianAt(truth, 1.0, 0.05, 0.05)});
    }
    tracker_.update(k * 33333, Pose2(), mixed(k));
  }
  EXPECT_GE(requests, 1);
  EXPECT_LT(last_request, 80);
  RecordProperty("requests_during_lasting_change", requests);
  expectFinite(tracker_);
}

TEST_F(HypothesisTrackerTest, DeterministicForTheSameInput) {
  testing::ScenarioConfig config;
  config.frames = 60;
  const auto frames = testing::makeScenario(field_, config);
  auto run = [&]() {
    HypothesisTracker t(index_, TrackerConfig{});
    t.applyHint(hint(HintKind::kResetTo,
                     {gaussianAt(Pose2(frames[0].field_T_robot.x + 0.1, frames[0].field_T_robot.y,
                                       frames[0].field_T_robot.theta),
                                 1.0, 0.1, 0.1),
                      gaussianAt(Pose2(0.0, 0.0, 1.0), 1.0, 0.1, 0.1)}));
    for (const auto& f : frames) t.update(f.t_us, f.odometry, f.points);
    return t.hypotheses();
  };
  const auto a = run(), b = run();
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].pose.mean.x, b[i].pose.mean.x);
    EXPECT_EQ(a[i].pose.covariance, b[i].pose.covariance);
    EXPECT_EQ(a[i].pose.weight, b[i].pose.weight);
  }
}

}  // namespace
}  // namespace houghloc
