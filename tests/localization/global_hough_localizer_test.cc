// GlobalHoughLocalizer::locate() end to end on hand-made and degenerate frames, and the
// negative evidence.
#include "localization/global_hough_localizer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "field_models/angles.h"
#include "field_models/standard_fields.h"
#include "localization/gaussian_pose.h"
#include "tools/synthetic/synthetic_ground_points.h"

namespace houghloc {
namespace {

bool near(const Pose2& a, const Pose2& b, double m, double rad) {
  return (a.translation() - b.translation()).norm() <= m &&
         std::abs(angleDifference(a.theta, b.theta)) <= rad;
}

/// Correct up to the field's point symmetry (DESIGN §5.3).
int rankOf(const std::vector<PoseHypothesis>& hs, const Pose2& truth) {
  const Pose2 mirrored(-truth.x, -truth.y, truth.theta + M_PI);
  for (std::size_t k = 0; k < hs.size(); ++k) {
    if (near(hs[k].field_T_robot, truth, 0.10, 3 * kDeg) ||
        near(hs[k].field_T_robot, mirrored, 0.10, 3 * kDeg)) {
      return static_cast<int>(k);
    }
  }
  return -1;
}

void expectWellFormed(const std::vector<PoseHypothesis>& hs, std::size_t max_count = 12) {
  EXPECT_LE(hs.size(), max_count);
  double sum = 0.0;
  for (const auto& h : hs) {
    EXPECT_TRUE(h.field_T_robot.isFinite());
    EXPECT_TRUE(h.covariance.allFinite());
    EXPECT_TRUE(std::isfinite(h.weight));
    EXPECT_GT(h.covariance(0, 0), 0.0);
    sum += h.weight;
  }
  if (!hs.empty()) {
    EXPECT_NEAR(sum, 1.0, 1e-9);
  }
  for (std::size_t k = 1; k < hs.size(); ++k) EXPECT_LE(hs[k].score, hs[k - 1].score + 1e-9);
}

class LocalizerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    field_ = new FieldModel(makeStandardField("spl"));
    localizer_ = new GlobalHoughLocalizer(*field_);
  }
  static void TearDownTestSuite() {
    delete localizer_;
    delete field_;
  }
  static FieldModel* field_;
  static GlobalHoughLocalizer* localizer_;
};
FieldModel* LocalizerTest::field_ = nullptr;
GlobalHoughLocalizer* LocalizerTest::localizer_ = nullptr;

TEST_F(LocalizerTest, DegenerateInputGivesNothingOrHeadingOnly) {
  GroundPoints frame;
  EXPECT_TRUE(localizer_->locate(frame).empty());  // no points
  GroundPoint one;
  one.p_robot = Eigen::Vector2d(1.0, 0.5);
  frame.points = {one};
  EXPECT_TRUE(localizer_->locate(frame).empty());  // one point
  frame.points.assign(500, one);
  EXPECT_TRUE(localizer_->locate(frame).empty());  // all on one spot
  GroundPoint nan;
  nan.p_robot = Eigen::Vector2d(std::numeric_limits<double>::quiet_NaN(), 1.0);
  GroundPoint inf;
  inf.p_robot = Eigen::Vector2d(std::numeric_limits<double>::infinity(), 1.0);
  GroundPoint bad_weight = one;
  bad_weight.weight = std::numeric_limits<double>::quiet_NaN();
  frame.points = {nan, inf, bad_weight, nan};
  EXPECT_TRUE(localizer_->locate(frame).empty());  // NaN points
  GroundPolygon nan_region = {Eigen::Vector2d(0, 0), Eigen::Vector2d(std::nan(""), 1),
                              Eigen::Vector2d(1, 1)};
  frame.visible_regions = {nan_region};
  EXPECT_TRUE(localizer_->locate(frame).empty());
}

TEST_F(LocalizerTest, NaNPointsAmongGoodOnesAreIgnored) {
  const Pose2 truth(-2.0, 1.0, 20 * kDeg);
  SyntheticConfig config;
  config.view = viewModel("kid-wide");
  SyntheticFrame f = generateFrame(*field_, truth, config);
  GroundPoint nan;
  nan.p_robot = Eigen::Vector2d(std::numeric_limits<double>::quiet_NaN(), 0.0);
  for (int k = 0; k < 20; ++k) f.ground.points.push_back(nan);
  const auto hs = localizer_->locate(f.ground);
  expectWellFormed(hs);
  EXPECT_GE(rankOf(hs, truth), 0);
}

TEST_F(LocalizerTest, HundredThousandRandomPointsDoNotBreakIt) {
  GroundPoints frame;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-6.0, 6.0);
  for (int k = 0; k < 100000; ++k) {
    GroundPoint g;
    g.p_robot = Eigen::Vector2d(u(rng), u(rng));
    frame.points.push_back(g);
  }
  expectWellFormed(localizer_->locate(frame));
}

TEST_F(LocalizerTest, HundredThousandLinePointsStillLocate) {
  const Pose2 truth(1.3, -0.4, -75 * kDeg);
  SyntheticConfig config;
  config.view = viewModel("kid-wide");
  config.point_spacing_m = 0.00013;  // ~100 000 points
  const SyntheticFrame f = generateFrame(*field_, truth, config);
  ASSERT_GT(f.ground.size(), 80000u);
  const auto hs = localizer_->locate(f.ground);
  expectWellFormed(hs);
  EXPECT_GE(rankOf(hs, truth), 0);
}

TEST_F(LocalizerTest, TwoPerpendicularLinesLocateAFieldCorner) {
  // Noise-free points of the left touch line and the opponent goal line, seen from (3.6, 2.2).
  const Pose2 truth(3.6, 2.2, 35 * kDeg);
  GroundPoints frame;
  const Pose2 robot_T_field = truth.inverse();
  for (double x = 2.5; x <= 4.5; x += 0.04) {
    GroundPoint g;
    g.p_robot = robot_T_field.transform({x, 3.0});
    frame.points.push_back(g);
  }
  for (double y = 1.5; y <= 3.0; y += 0.04) {
    GroundPoint g;
    g.p_robot = robot_T_field.transform({4.5, y});
    frame.points.push_back(g);
  }
  const auto hs = localizer_->locate(frame);
  expectWellFormed(hs);
  const int rank = rankOf(hs, truth);
  ASSERT_GE(rank, 0);  // without a visible region the T-junctions fit as well: any rank
  const Pose2 best = hs[rank].field_T_robot;
  const Pose2 target =
      std::abs(best.x - truth.x) < 1.0 ? truth : Pose2(-3.6, -2.2, truth.theta + M_PI);
  EXPECT_LT((best.translation() - target.translation()).norm(), 0.01);
  EXPECT_LT(std::abs(angleDifference(best.theta, target.theta)), 0.2 * kDeg);
  EXPECT_EQ(hs[rank].kind, HypothesisKind::kFull);
}

TEST_F(LocalizerTest, ParallelLinesOnlyGiveALargeVarianceAlongThem) {
  // Only the left touch line in view (robot looking at it from 1.2 m), no visible region.
  const Pose2 truth(0.7, 1.8, 80 * kDeg);
  GroundPoints frame;
  const Pose2 robot_T_field = truth.inverse();
  for (double x = -0.3; x <= 1.9; x += 0.04) {
    GroundPoint g;
    g.p_robot = robot_T_field.transform({x, 3.0});
    frame.points.push_back(g);
  }
  const auto hs = localizer_->locate(frame);
  expectWellFormed(hs);
  ASSERT_FALSE(hs.empty());
  bool found = false;
  for (const auto& h : hs) {
    EXPECT_EQ(h.kind, HypothesisKind::kParallel);
    const double along =
        h.line_direction.dot(h.covariance.topLeftCorner<2, 2>() * h.line_direction);
    EXPECT_GT(std::sqrt(along), 0.3);
    // The truth (or its mirror) lies on the hypothesis' line within 3 cm and 1 deg.
    for (const Pose2& t : {truth, Pose2(-truth.x, -truth.y, truth.theta + M_PI)}) {
      const Eigen::Vector2d d = t.translation() - h.field_T_robot.translation();
      const Eigen::Vector2d n(-h.line_direction.y(), h.line_direction.x());
      found |= std::abs(d.dot(n)) < 0.03 &&
               std::abs(angleDifference(h.field_T_robot.theta, t.theta)) < kDeg;
    }
  }
  EXPECT_TRUE(found);
}

TEST_F(LocalizerTest, CentreCircleAloneLocatesUpToSymmetry) {
  // Standing in the centre circle looking along the halfway line: circle and halfway line only.
  const Pose2 truth(0.3, -0.2, 95 * kDeg);
  SyntheticConfig config;
  config.view = viewModel("nao-top");
  config.view.max_range_m = 1.5;
  config.marks = false;
  const SyntheticFrame f = generateFrame(*field_, truth, config);
  const auto hs = localizer_->locate(f.ground);
  expectWellFormed(hs);
  const int rank = rankOf(hs, truth);
  ASSERT_GE(rank, 0);
  EXPECT_LE(rank, 1);
}

TEST_F(LocalizerTest, TwinsOnAPointSymmetricFieldAreExactMirrors) {
  // Each candidate stands for itself and its twin (-x, -y, theta + pi), which explains the frame
  // alike: refined once, the twin is its mirror with the same score (two refinements ended a few
  // millimetres apart and took two slots).
  int pairs = 0;
  for (int k = 0; k < 12; ++k) {
    SyntheticConfig config;
    config.view = viewModel(k % 2 == 0 ? "kid-wide" : "nao-top");
    config.seed = 300 + k;
    const Pose2 truth(-4.0 + 0.7 * k, 2.5 - 0.45 * k, 0.55 * k);
    const auto hs = localizer_->locate(generateFrame(*field_, truth, config).ground);
    expectWellFormed(hs);
    for (const PoseHypothesis& h : hs) {
      for (const PoseHypothesis& other : hs) {
        // Same kind and within 2 cm: hypotheses of a kind closer than 0.25 m are merged.
        if (&other == &h || other.kind != h.kind ||
            !near(other.field_T_robot, mirrored(h.field_T_robot), 0.02, 0.01)) {
          continue;
        }
        ++pairs;
        const Pose2 twin = mirrored(h.field_T_robot);
        EXPECT_EQ(other.field_T_robot.x, twin.x) << "frame " << k;
        EXPECT_EQ(other.field_T_robot.y, twin.y) << "frame " << k;
        EXPECT_NEAR(angleDifference(other.field_T_robot.theta, twin.theta), 0.0, 1e-12);
        EXPECT_EQ(other.score, h.score) << "frame " << k;
      }
    }
  }
  EXPECT_GE(pairs, 24);  // every frame has pairs (each counted from both sides)
}

TEST_F(LocalizerTest, NegativeEvidencePenalisesLinesExpectedButNotSeen) {
  // The robot faces the left touch line from 2 m and sees 3 m of it in a 2.4 m x 3 m region.
  // Sliding along the line fits the points as well, but at x = -0.3 the halfway line would
  // cross the seen region, and no point lies on it.
  const Pose2 truth(-1.6, 1.0, M_PI / 2);
  const Pose2 slid(-0.3, 1.0, M_PI / 2);
  GroundPoints frame;
  for (double y = -1.5; y <= 1.5; y += 0.05) {
    GroundPoint g;
    g.p_robot = Eigen::Vector2d(2.0, y);
    frame.points.push_back(g);
  }
  frame.visible_regions = {{{0.2, -1.5}, {2.6, -1.5}, {2.6, 1.5}, {0.2, 1.5}}};
  WeightedPoints pts;
  for (const auto& g : frame.points) {
    pts.points.push_back(g.p_robot);
    pts.weights.push_back(1.0);
  }
  const ScoringConfig scoring;
  const DistanceGrid& grid = localizer_->map().grid();
  EXPECT_NEAR(scorePose(pts, slid, grid, scoring).score, scorePose(pts, truth, grid, scoring).score,
              1e-3 * pts.totalWeight());  // positive evidence cannot tell them apart
  const VisibilityEvidence evidence(frame, pts, NegativeEvidenceConfig{});
  ASSERT_FALSE(evidence.empty());
  EXPECT_NEAR(evidence.pointDensity(), 20.0, 5.0);  // 20 points per metre of line
  EXPECT_LT(evidence.unseenLineLength(truth, localizer_->map()), 0.15);
  EXPECT_NEAR(evidence.unseenLineLength(slid, localizer_->map()), 1.2, 0.3);
  EXPECT_GT(evidence.penalty(slid, localizer_->map()), 5.0);
  // Green beyond the carpet: 1.5 m further out, the region (field y 2.7 to 5.1) reaches 1.1 m
  // past the tolerated edge (3.7 m carpet + 0.3 m), over its 3 m width.
  const Pose2 outside(-1.6, 2.5, M_PI / 2);
  EXPECT_NEAR(evidence.greenOutsideCarpet(outside, *field_), 3.0 * 1.1, 0.4);
  EXPECT_LT(evidence.greenOutsideCarpet(truth, *field_), 1e-9);
}

}  // namespace
}  // namespace houghloc
