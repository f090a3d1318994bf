// Paper step 4 (solving, scoring, pruning, refinement, merging) and the landmarks.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "field_models/angles.h"
#include "field_models/standard_fields.h"
#include "localization/hypothesis_set.h"
#include "localization/landmarks.h"
#include "localization/map_signature.h"
#include "localization/pose_refinement.h"
#include "localization/pose_scoring.h"
#include "localization/pose_solver.h"

namespace houghloc {
namespace {

/// Map samples seen from field_T_robot within `range` (robot frame), weight 1.
WeightedPoints view(const FieldModel& field, const Pose2& field_T_robot, double range,
                    double noise = 0.0, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, noise > 0.0 ? noise : 1.0);
  WeightedPoints all = sampleMapLines(field, 0.05, false);
  WeightedPoints out;
  const Pose2 robot_T_field = field_T_robot.inverse();
  for (const auto& p : all.points) {
    Eigen::Vector2d q = robot_T_field.transform(p);
    if (q.norm() > range) continue;
    if (noise > 0.0) q += noise * Eigen::Vector2d(n(rng), n(rng));
    out.points.push_back(q);
    out.weights.push_back(1.0);
  }
  return out;
}

TEST(PoseSolver, TwoPerpendicularConstraintsSolveExactly) {
  std::vector<TranslationConstraint> c = {{0, 0.0, 1.25, 10.0}, {1, M_PI / 2, -0.4, 10.0}};
  Eigen::Vector2d t;
  Eigen::Matrix2d cov;
  ASSERT_TRUE(solveTranslation(c, 0.03, &t, &cov));
  EXPECT_NEAR(t.x(), 1.25, 1e-12);
  EXPECT_NEAR(t.y(), -0.4, 1e-12);
  EXPECT_NEAR(cov(0, 0), 0.03 * 0.03, 1e-12);
  EXPECT_NEAR(cov(0, 1), 0.0, 1e-12);
  // Oblique: T . (cos 45, sin 45) = 1/sqrt(2) and T_x = 0 give T = (0, 1).
  c = {{0, 0.0, 0.0, 1.0}, {1, M_PI / 4, std::sqrt(0.5), 1.0}};
  ASSERT_TRUE(solveTranslation(c, 0.03, &t, &cov));
  EXPECT_NEAR(t.y(), 1.0, 1e-12);
  EXPECT_GT(cov(1, 1), cov(0, 0));               // the oblique pair constrains y less well
  c = {{0, 0.0, 1.0, 1.0}, {0, 0.0, 2.0, 1.0}};  // parallel
  EXPECT_FALSE(solveTranslation(c, 0.03, &t, &cov));
}

TEST(PoseSolver, ParallelOnlyGivesOneDimensionalGaussians) {
  std::vector<std::vector<TranslationConstraint>> per_direction(2);
  per_direction[1] = {{1, M_PI / 2, 2.5, 20.0}, {1, M_PI / 2, -0.5, 10.0}};
  PoseSolverConfig config;
  const auto poses = solvePoses(0.3, per_direction, config);
  ASSERT_EQ(poses.size(), 2u);
  for (const auto& h : poses) {
    EXPECT_EQ(h.kind, HypothesisKind::kParallel);
    EXPECT_NEAR(std::abs(h.line_direction.x()), 1.0, 1e-12);  // along the lines y = const
    EXPECT_NEAR(h.covariance(0, 0), config.sigma_along_m * config.sigma_along_m, 1e-9);
    EXPECT_NEAR(h.covariance(1, 1), config.sigma_rho_m * config.sigma_rho_m, 1e-9);
    EXPECT_NEAR(h.field_T_robot.theta, 0.3, 1e-12);
  }
  EXPECT_NEAR(poses[0].field_T_robot.y, 2.5, 1e-12);
  // No constraint at all: heading only.
  const auto none = solvePoses(-1.0, {{}, {}}, config);
  ASSERT_EQ(none.size(), 1u);
  EXPECT_EQ(none[0].kind, HypothesisKind::kHeadingOnly);
  EXPECT_GT(none[0].covariance(0, 0), 50.0);
}

TEST(PoseSolver, LineCandidatesTryEveryShiftOfTheStrongestDirection) {
  // Direction 1 (lines y = const) carries the seen line: each shift aligns it with one map line.
  std::vector<std::vector<TranslationConstraint>> per_direction(2);
  per_direction[0] = {{0, 0.0, 1.0, 6.0}};
  per_direction[1] = {{1, M_PI / 2, 2.5, 20.0}, {1, M_PI / 2, -0.5, 20.0}, {1, M_PI / 2, 1.1, 9.0}};
  const auto lines = lineCandidates(0.3, per_direction, PoseSolverConfig());
  ASSERT_EQ(lines.size(), 3u);
  const double y[3] = {2.5, -0.5, 1.1};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(lines[k].kind, HypothesisKind::kParallel);
    EXPECT_NEAR(lines[k].field_T_robot.y, y[k], 1e-12);
    EXPECT_NEAR(lines[k].field_T_robot.theta, 0.3, 1e-12);
    EXPECT_NEAR(std::abs(lines[k].line_direction.x()), 1.0, 1e-12);
  }
  EXPECT_TRUE(lineCandidates(0.3, {{}, {}}, PoseSolverConfig()).empty());
}

TEST(Landmarks, CircleFromAShortArcOfALargeCircleButNotFromATangentLine) {
  LandmarkConfig config;
  // 0.75 rad of a 2 m circle (the MSL centre circle seen from afar) is accepted ...
  WeightedPoints arc;
  for (double a = -0.375; a <= 0.375 + 1e-9; a += 0.02) {
    arc.points.push_back(Eigen::Vector2d(3.0, 0.5) +
                         2.0 * Eigen::Vector2d(std::cos(a), std::sin(a)));
    arc.weights.push_back(1.0);
  }
  const auto seen = fitCircle(arc, 2.0, config);
  ASSERT_TRUE(seen.has_value());
  EXPECT_LT((seen->center - Eigen::Vector2d(3.0, 0.5)).norm(), 0.05);
  // ... but a straight 1.2 m line is not a 0.75 m circle, whose tangent stays within the band
  // for 0.8 rad.
  WeightedPoints line;
  for (double y = -0.6; y <= 0.6 + 1e-9; y += 0.02) {
    line.points.push_back(Eigen::Vector2d(2.0, y));
    line.weights.push_back(1.0);
  }
  EXPECT_FALSE(fitCircle(line, 0.75, config).has_value());
}

TEST(Landmarks, FitsASingleCircleOfKnownRadius) {
  WeightedPoints pts;
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 0.01);
  const Eigen::Vector2d centre(2.0, -0.7);
  for (double a = -1.2; a <= 1.6; a += 0.04) {  // 160 deg of the circle
    pts.points.push_back(centre + 0.75 * Eigen::Vector2d(std::cos(a), std::sin(a)) +
                         Eigen::Vector2d(n(rng), n(rng)));
    pts.weights.push_back(1.0);
  }
  const auto circle = fitCircle(pts, 0.75, LandmarkConfig{});
  ASSERT_TRUE(circle.has_value());
  EXPECT_LT((circle->center - centre).norm(), 0.01);
  EXPECT_GT(circle->arc_rad, 2.5);
  // A straight line is not a circle.
  WeightedPoints line;
  for (double y = -2.0; y <= 2.0; y += 0.04) {
    line.points.emplace_back(1.5, y);
    line.weights.push_back(1.0);
  }
  EXPECT_FALSE(fitCircle(line, 0.75, LandmarkConfig{}).has_value());
  // Circle centre (robot frame) + heading -> pose: the centre lands on the field origin.
  const auto poses = landmarkCandidates(centre, {0, 0}, {{0.5, 1.0}}, HypothesisSource::kCircle, 1);
  ASSERT_EQ(poses.size(), 1u);
  EXPECT_LT(poses[0].field_T_robot.transform(centre).norm(), 1e-12);
}

TEST(Landmarks, FindsAnIsolatedMarkBlobButNotLines) {
  WeightedPoints pts;
  for (double t = -0.05; t <= 0.051; t += 0.025) {
    pts.points.emplace_back(3.0 + t, 0.2);
    pts.points.emplace_back(3.0, 0.2 + t);
  }
  for (double y = -2.0; y <= 2.0; y += 0.05) pts.points.emplace_back(1.0, y);
  pts.weights.assign(pts.points.size(), 1.0);
  const auto blobs = findMarkBlobs(pts, 0.1, LandmarkConfig{});
  ASSERT_EQ(blobs.size(), 1u);
  EXPECT_LT((blobs[0] - Eigen::Vector2d(3.0, 0.2)).norm(), 0.02);
}

TEST(Scoring, PruningDropsPosesOnLineExtensions) {
  // A field corner seen from inside; the same two lines also fit the three other quarter-turn
  // poses around the corner point, which put the points off the field, on line extensions.
  const FieldModel field = makeStandardField("spl");
  MapSignature map(field);
  const Pose2 truth(3.5, 2.2, 40 * kDeg);
  const WeightedPoints pts = view(field, truth, 1.6);
  const Eigen::Vector2d corner(4.5, 3.0);
  std::vector<PoseHypothesis> candidates;
  for (int k = 0; k < 4; ++k) {
    const Pose2 rotate_about_corner =
        Pose2(corner.x(), corner.y(), k * M_PI / 2) * Pose2(-corner.x(), -corner.y(), 0.0);
    PoseHypothesis h;
    h.field_T_robot = rotate_about_corner * truth;
    const PoseScore s = scorePose(pts, h.field_T_robot, map.grid(), ScoringConfig{});
    h.score = s.score;
    h.inlier_share = s.inlier_share;
    candidates.push_back(h);
  }
  EXPECT_NEAR(candidates[0].inlier_share, 1.0, 1e-9);
  const auto kept = pruneCandidates(candidates, PruningConfig{});
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_NEAR(kept[0].field_T_robot.x, truth.x, 1e-9);
}

TEST(Refinement, ConvergesBelowTheBinSize) {
  const FieldModel field = makeStandardField("kid");
  MapSignature map(field);
  const Pose2 truth(-2.2, 1.4, -130 * kDeg);
  const WeightedPoints pts = view(field, truth, 3.5, 0.01, 7);
  const Pose2 start(truth.x + 0.05, truth.y - 0.03, truth.theta + 1.0 * kDeg);
  const RefinementResult r = refinePose(pts, start, map.features(), RefinementConfig{});
  EXPECT_LT((r.field_T_robot.translation() - truth.translation()).norm(), 0.005);
  EXPECT_LT(std::abs(angleDifference(r.field_T_robot.theta, truth.theta)), 0.1 * kDeg);
  EXPECT_LT(r.rms_m, 0.02);
  EXPECT_GT(r.covariance(0, 0), 0.0);
  EXPECT_LT(std::sqrt(r.covariance(0, 0)), 0.05);
}

TEST(Refinement, FrozenDirectionDoesNotMove) {
  const FieldModel field = makeStandardField("spl");
  MapSignature map(field);
  const Pose2 truth(-1.0, 2.6, 0.0);
  const WeightedPoints pts = view(field, truth, 1.0);  // the touch line y = 3 only
  const Pose2 start(-0.8, 2.63, 0.5 * kDeg);
  const RefinementResult r =
      refinePose(pts, start, map.features(), RefinementConfig{}, Eigen::Vector2d(1.0, 0.0));
  EXPECT_NEAR(r.field_T_robot.x, -0.8, 1e-4);
  EXPECT_NEAR(r.field_T_robot.y, 2.6, 0.003);
}

TEST(HypothesisSet, MergesDuplicatesAndNormalisesWeights) {
  std::vector<PoseHypothesis> hs(4);
  hs[0].field_T_robot = Pose2(1.0, 1.0, 0.1);
  hs[0].score = 50.0;
  hs[1].field_T_robot = Pose2(1.05, 1.0, 0.12);  // duplicate of 0
  hs[1].score = 49.0;
  hs[2].field_T_robot = Pose2(-1.0, -1.0, 0.1 + M_PI);
  hs[2].score = 50.0;
  hs[3].field_T_robot = Pose2(3.0, 0.0, 0.0);
  hs[3].score = 20.0;
  HypothesisSetConfig config;
  auto out = mergeDuplicates(hs, config);
  ASSERT_EQ(out.size(), 3u);
  normalizeWeights(out, config);
  double sum = 0.0;
  for (const auto& h : out) sum += h.weight;
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_NEAR(out[0].weight, out[1].weight, 1e-12);  // symmetric twins weigh the same
  EXPECT_LT(out[2].weight, 1e-4);
  config.max_hypotheses = 2;
  EXPECT_EQ(mergeDuplicates(hs, config).size(), 2u);
}

}  // namespace
}  // namespace houghloc
