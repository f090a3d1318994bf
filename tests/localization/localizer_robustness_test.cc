// Issue 8 robustness: odometry jumps, time going backwards, NaN odometry, NaN/inf points, frames
// without points; no crash, finite outputs, a status that says so, deterministic output.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "field_models/standard_fields.h"
#include "localization/localizer.h"
#include "tests/localization/localizer_test_support.h"

namespace houghloc {
namespace {

using testing::estimateCorrect;
using testing::estimateFinite;
using testing::ScenarioFrame;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// Runs a Localizer over frames; `edit` may change each frame's input before it is processed.
struct FrameRun {
  std::vector<LocalizationEstimate> estimates;
  int first_bad = -1;  ///< first frame with a non-finite estimate
};

template <typename Edit>
FrameRun runFrames(Localizer& localizer, std::vector<ScenarioFrame> frames, Edit edit) {
  FrameRun run;
  for (size_t k = 0; k < frames.size(); ++k) {
    ScenarioFrame& f = frames[k];
    std::optional<Pose2> odometry = f.odometry;
    edit(static_cast<int>(k), &f, &odometry);
    run.estimates.push_back(
        localizer.process(f.t_us, odometry, {testing::uprightCamera()}, f.points));
    if (run.first_bad < 0 && !estimateFinite(run.estimates.back())) run.first_bad = k;
  }
  return run;
}

class LocalizerRobustness : public ::testing::Test {
 protected:
  LocalizerRobustness()
      : field_(makeStandardField("spl")),
        frames_(testing::makeScenario(field_, testing::walkOn(field_, 360, 17))),
        localizer_(field_) {
    LocalizationHint start;
    start.kind = HintKind::kResetTo;
    GaussianPose pose;
    pose.mean = frames_[0].field_T_robot;
    pose.covariance = Eigen::Vector3d(0.01, 0.01, 0.003).asDiagonal();
    start.poses = {pose};
    localizer_.applyHint(start);
  }

  /// Share of the frames in [from, to) whose best pose is correct up to symmetry.
  double correctShare(const FrameRun& run, int from, int to) const {
    int correct = 0;
    for (int k = from; k < to; ++k) {
      correct += estimateCorrect(run.estimates[k], frames_[k].field_T_robot) ? 1 : 0;
    }
    return static_cast<double>(correct) / (to - from);
  }

  FieldModel field_;
  std::vector<ScenarioFrame> frames_;
  Localizer localizer_;
};

TEST_F(LocalizerRobustness, OdometryJumps) {
  // The odometry source resets twice (a 3 m / 2 rad offset appears from one frame to the next).
  const FrameRun run =
      runFrames(localizer_, frames_, [](int k, ScenarioFrame*, std::optional<Pose2>* o) {
        if (k >= 100) **o = Pose2(3.0, -3.0, 2.0) * **o;
        if (k >= 200) **o = Pose2(-50.0, 7.0, -1.0) * **o;
      });
  EXPECT_EQ(run.first_bad, -1);
  EXPECT_GE(correctShare(run, 0, 360), 0.97);
}

TEST_F(LocalizerRobustness, TimeGoingBackwards) {
  const FrameRun run = runFrames(localizer_, frames_, [](int k, ScenarioFrame* f, auto*) {
    if (k >= 100 && k < 110) f->t_us -= 2000000;  // a clock glitch of 2 s
    if (k >= 200) f->t_us -= 5000000;             // and a clock reset
  });
  EXPECT_EQ(run.first_bad, -1);
  EXPECT_GE(correctShare(run, 0, 360), 0.97);
}

TEST_F(LocalizerRobustness, NanOdometry) {
  const FrameRun run = runFrames(localizer_, frames_, [](int k, ScenarioFrame*, auto* o) {
    if (k >= 50 && k < 150) *o = Pose2(kNan, 0.0, 0.0);
    if (k >= 150 && k < 160) *o = Pose2(0.0, kInf, 0.0);
    if (k >= 250 && k < 260) o->reset();
  });
  EXPECT_EQ(run.first_bad, -1);
  // Without odometry, a view of parallel lines leaves the position along them open: the estimate
  // may drift along the lines, but its covariance has to say so.
  // (A correction that overshoots along the lines when their end comes into view is allowed for a
  // few frames.)
  int inconsistent = 0;
  for (int k = 50; k < 200; ++k) {
    const GaussianPose best = *run.estimates[k].best();
    const double error = (best.mean.translation() - frames_[k].field_T_robot.translation()).norm();
    const double sigma =
        std::sqrt(best.covariance.topLeftCorner<2, 2>().eigenvalues().real().maxCoeff());
    inconsistent += error > 0.05 + 3.0 * sigma ? 1 : 0;
  }
  EXPECT_LE(inconsistent, 3);
  EXPECT_GE(correctShare(run, 0, 360), 0.85);
  EXPECT_GE(correctShare(run, 200, 360), 0.97);
}

TEST_F(LocalizerRobustness, NanAndInfPoints) {
  const FrameRun run = runFrames(localizer_, frames_, [](int k, ScenarioFrame* f, auto*) {
    if (f->points.points.size() < 4) return;
    f->points.points[0].p_robot.x() = kNan;
    f->points.points[1].p_robot.y() = kInf;
    f->points.points[2].weight = kNan;
    f->points.points[3].weight = -kInf;
    f->points.visible_regions = {{{0.0, 0.0}, {kNan, 1.0}, {1.0, 1.0}}};
    // Field-edge samples that no use may trust, next to whatever the scenario has.
    for (const FieldEdgePoint& bad :
         {FieldEdgePoint{{kNan, 1.0}, 0.1, 0}, FieldEdgePoint{{1.0, kInf}, 0.1, 0},
          FieldEdgePoint{{3.0, 0.0}, kNan, 0}, FieldEdgePoint{{3.0, 1.0}, -1.0, 0},
          FieldEdgePoint{{0.0, 0.0}, 0.1, 0}, FieldEdgePoint{{1e12, 0.0}, kInf, 0}}) {
      f->points.field_edge.push_back(bad);
    }
    if (k % 50 == 0) {
      for (GroundPoint& p : f->points.points) p.p_robot = Eigen::Vector2d(kNan, kNan);
    }
  });
  EXPECT_EQ(run.first_bad, -1);
  EXPECT_GE(correctShare(run, 0, 360), 0.97);
  for (const LocalizationEstimate& e : run.estimates) EXPECT_GE(e.points_in, 0);
  EXPECT_EQ(run.estimates[50].points_in, 0);
}

TEST_F(LocalizerRobustness, TenSecondsWithoutPoints) {
  // 60 frames tracked, then 10 s (300 frames) seeing nothing while walking, then lines again.
  std::vector<ScenarioFrame> frames =
      testing::makeScenario(field_, testing::walkOn(field_, 420, 17));
  frames_ = frames;
  const FrameRun run = runFrames(localizer_, frames, [](int k, ScenarioFrame* f, auto*) {
    if (k >= 60 && k < 360) f->points.points.clear();
  });
  EXPECT_EQ(run.first_bad, -1);
  EXPECT_NE(run.estimates[100].status, TrackerStatus::kLost);  // 1.3 s: odometry still good
  EXPECT_EQ(run.estimates[359].status, TrackerStatus::kLost);  // 10 s of dead reckoning
  EXPECT_EQ(run.estimates[359].points_in, 0);
  EXPECT_TRUE(run.estimates[360].global_ran);  // lines again: ask the global localizer
  EXPECT_GE(correctShare(run, 380, 420), 0.95);
  EXPECT_NE(run.estimates.back().status, TrackerStatus::kLost);
}

TEST_F(LocalizerRobustness, NothingAtAllFromUnknownStart) {
  Localizer fresh(field_);
  const FrameRun run = runFrames(fresh, frames_, [](int, ScenarioFrame* f, auto* o) {
    f->points.points.clear();
    *o = Pose2(kNan, kNan, kNan);
  });
  EXPECT_EQ(run.first_bad, -1);
  for (const LocalizationEstimate& e : run.estimates) {
    EXPECT_EQ(e.status, TrackerStatus::kInitializing);
    EXPECT_TRUE(e.hypotheses.empty());
  }
}

TEST_F(LocalizerRobustness, SameInputSameOutput) {
  // Unknown start, a kidnap and odometry trouble: everything the facade does, twice.
  testing::ScenarioConfig config = testing::walkOn(field_, 300, 21);
  config.kidnap_frame = 150;
  config.kidnap_to = Pose2(-2.5, 1.0, -0.5);
  const auto frames = testing::makeScenario(field_, config);
  auto edit = [](int k, ScenarioFrame*, std::optional<Pose2>* o) {
    if (k % 37 == 0) o->reset();
  };
  Localizer a(field_), b(field_);
  const FrameRun first = runFrames(a, frames, edit);
  const FrameRun second = runFrames(b, frames, edit);
  ASSERT_EQ(first.estimates.size(), second.estimates.size());
  for (size_t k = 0; k < first.estimates.size(); ++k) {
    ASSERT_TRUE(testing::sameEstimate(first.estimates[k], second.estimates[k])) << k;
  }
  // A copy carries on exactly like the original.
  Localizer copy = a;
  const std::vector<ScenarioFrame> more(frames.begin() + 100, frames.begin() + 140);
  const FrameRun from_a = runFrames(a, more, edit), from_copy = runFrames(copy, more, edit);
  for (size_t k = 0; k < more.size(); ++k) {
    ASSERT_TRUE(testing::sameEstimate(from_a.estimates[k], from_copy.estimates[k])) << k;
  }
}

}  // namespace
}  // namespace houghloc
