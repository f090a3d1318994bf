// Tracking accuracy on synthetic walks (issue 8 targets, DESIGN §5.3 metrics).
#include <gtest/gtest.h>

#include <algorithm>

#include "field_models/standard_fields.h"
#include "localization/hypothesis_tracker.h"
#include "tests/localization/tracking_scenario.h"

namespace houghloc {
namespace {

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * (v.size() - 1) + 0.5)];
}

GaussianPose around(const Pose2& pose, double dx, double dy, double dtheta) {
  GaussianPose g;
  g.mean = Pose2(pose.x + dx, pose.y + dy, pose.theta + dtheta);
  g.covariance = Eigen::Vector3d(0.04, 0.04, 0.01).asDiagonal();  // 20 cm, 6 deg
  return g;
}

bool correct(const Pose2& estimate, const Pose2& truth) {  // DESIGN §5.3: 0.10 m and 3 deg
  return (estimate.translation() - truth.translation()).norm() <= 0.10 &&
         std::abs(angleDifference(estimate.theta, truth.theta)) <= 3.0 * M_PI / 180.0;
}

struct Errors {
  std::vector<double> position_m, heading_rad;
  int flips = 0;
};

struct AccuracyCase {
  const char* field;
  std::uint32_t seed;
};

class TrackingAccuracy : public ::testing::TestWithParam<AccuracyCase> {};

TEST_P(TrackingAccuracy, WalkWithNoisyOdometryMeetsTargets) {
  const FieldModel field = makeStandardField(GetParam().field);
  testing::ScenarioConfig config;
  config.seed = GetParam().seed;
  config.half_extent_x_m = 0.33 * field.field_length;
  config.half_extent_y_m = 0.3 * field.field_width;
  // Adult-size and MSL cameras sit higher and see farther: range scales with the field, so the
  // robot sees lines about as often as on the SPL field.
  config.max_range_m *= std::max(1.0, field.field_length / 9.0);
  const auto frames = testing::makeScenario(field, config);
  HypothesisTracker tracker(field);
  LocalizationHint start;
  start.kind = HintKind::kResetTo;
  start.poses = {around(frames[0].field_T_robot, 0.1, -0.1, 0.05)};  // start hint, 14 cm off
  tracker.applyHint(start);
  Errors errors;
  bool scoring = false;
  for (const auto& f : frames) {
    tracker.update(f.t_us, f.odometry, f.points);
    ASSERT_FALSE(tracker.hypotheses().empty());
    const Pose2& best = tracker.hypotheses().front().pose.mean;
    ASSERT_TRUE(best.isFinite());
    scoring = scoring || correct(best, f.field_T_robot);
    if (!scoring) continue;
    const double e = (best.translation() - f.field_T_robot.translation()).norm();
    errors.position_m.push_back(e);
    errors.heading_rad.push_back(std::abs(angleDifference(best.theta, f.field_T_robot.theta)));
    const double e_mirror = (best.translation() - mirrored(f.field_T_robot).translation()).norm();
    errors.flips += (e_mirror < e && e > 0.5) ? 1 : 0;
  }
  ASSERT_GT(errors.position_m.size(), frames.size() - 5);
  const double median = percentile(errors.position_m, 0.5),
               p95 = percentile(errors.position_m, 0.95);
  const double heading = percentile(errors.heading_rad, 0.5) * 180.0 / M_PI;
  RecordProperty("median_position_m", std::to_string(median));
  RecordProperty("p95_position_m", std::to_string(p95));
  RecordProperty("median_heading_deg", std::to_string(heading));
  EXPECT_LE(median, 0.03);
  EXPECT_LE(p95, 0.10);
  EXPECT_LE(heading, 1.0);
  EXPECT_EQ(errors.flips, 0);
}

INSTANTIATE_TEST_SUITE_P(Fields, TrackingAccuracy,
                         ::testing::Values(AccuracyCase{"spl", 11}, AccuracyCase{"spl", 23},
                                           AccuracyCase{"spl2019", 5}, AccuracyCase{"kid", 8},
                                           AccuracyCase{"adult", 3}, AccuracyCase{"msl", 4}));

/// After a kidnap the tracker notices the disagreement, asks for global hypotheses and recovers
/// from injected candidates (true pose, its mirror and two wrong ones, as a global localizer
/// would give for a local view) without a reset.
TEST(TrackingRecovery, KidnapWithInjectedGlobalHypotheses) {
  const FieldModel field = makeStandardField("spl");
  testing::ScenarioConfig config;
  config.seed = 31;
  config.frames = 450;
  config.kidnap_frame = 300;
  config.kidnap_to = Pose2(-2.5, 1.0, -0.5);
  const auto frames = testing::makeScenario(field, config);
  HypothesisTracker tracker(field);
  LocalizationHint start;
  start.kind = HintKind::kResetTo;
  start.poses = {around(frames[0].field_T_robot, 0.05, 0.05, 0.02)};
  tracker.applyHint(start);
  int recovered_at = -1, injections = 0, asked_at = -1;
  for (int k = 0; k < static_cast<int>(frames.size()); ++k) {
    const auto& f = frames[k];
    tracker.update(f.t_us, f.odometry, f.points);
    if (tracker.needsGlobalHypotheses()) {
      if (k >= config.kidnap_frame && asked_at < 0) asked_at = k;
      // Global-like hypotheses: 5 cm / 2 deg off the truth, the mirror, two wrong poses.
      const Pose2& t = f.field_T_robot;
      tracker.injectHypotheses(
          {around(t, 0.05, -0.03, 0.03), mirrored(around(t, 0.05, -0.03, 0.03)),
           around(Pose2(1.0, 2.0, 1.0), 0, 0, 0), around(Pose2(-3.5, -1.0, -2.0), 0, 0, 0)});
      ++injections;
    }
    const Pose2& best = tracker.hypotheses().front().pose.mean;
    if (k < config.kidnap_frame) {
      ASSERT_TRUE(correct(best, f.field_T_robot)) << "frame " << k;
    } else if (recovered_at < 0 &&
               (correct(best, f.field_T_robot) || correct(best, mirrored(f.field_T_robot)))) {
      recovered_at = k;
    }
  }
  ASSERT_GE(recovered_at, 0);
  RecordProperty("asked_after_frames", std::to_string(asked_at - config.kidnap_frame));
  RecordProperty("recovered_after_frames", std::to_string(recovered_at - config.kidnap_frame));
  EXPECT_LE(asked_at - config.kidnap_frame, 10);      // noticed within disagree_frames + a few
  EXPECT_LE(recovered_at - config.kidnap_frame, 30);  // issue 8: within 30 frames
  const Pose2& truth = frames.back().field_T_robot;
  const Pose2& best = tracker.hypotheses().front().pose.mean;
  EXPECT_TRUE(correct(best, truth) || correct(best, mirrored(truth)));
  // The own-half prior separates the mirror pair (the robot was carried into its own half).
  LocalizationHint own_half;
  own_half.kind = HintKind::kOwnHalf;
  tracker.applyHint(own_half);
  EXPECT_TRUE(correct(tracker.hypotheses().front().pose.mean, truth));
  EXPECT_EQ(tracker.status(), TrackerStatus::kTracking);
}

}  // namespace
}  // namespace houghloc
