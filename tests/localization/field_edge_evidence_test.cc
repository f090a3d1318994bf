// FieldEdgeEvidence and rangeToRectangle against hand-computed carpet geometry, and the case it
// exists for: a lone arc of the MSL centre circle.
#include "localization/field_edge_evidence.h"

#include <gtest/gtest.h>

#include <cmath>

#include "field_models/standard_fields.h"
#include "localization/gaussian_pose.h"
#include "localization/global_hough_localizer.h"
#include "localization/negative_evidence.h"
#include "tools/synthetic/synthetic_ground_points.h"

namespace houghloc {
namespace {

TEST(RangeToRectangle, HandComputedRays) {
  // 10.4 x 7.4 m carpet (SPL): half extents 5.2 x 3.7.
  EXPECT_DOUBLE_EQ(rangeToRectangle({0.0, 0.0}, {1.0, 0.0}, 5.2, 3.7), 5.2);
  EXPECT_DOUBLE_EQ(rangeToRectangle({1.0, 0.0}, {-1.0, 0.0}, 5.2, 3.7), 6.2);
  EXPECT_DOUBLE_EQ(rangeToRectangle({0.0, 1.0}, {0.0, 1.0}, 5.2, 3.7), 2.7);
  // 45 deg from the centre: the long side's wall at y = 3.7 comes first, after 3.7 sqrt(2).
  const Eigen::Vector2d diagonal = Eigen::Vector2d(1.0, 1.0).normalized();
  EXPECT_NEAR(rangeToRectangle({0.0, 0.0}, diagonal, 5.2, 3.7), 3.7 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(rangeToRectangle({6.0, 0.0}, {-1.0, 0.0}, 5.2, 3.7), 0.0);  // outside
}

GroundPoints edgeSamples(const std::vector<Eigen::Vector2d>& points, double sigma) {
  GroundPoints frame;
  for (const auto& p : points) frame.field_edge.push_back({p, sigma, 0});
  return frame;
}

TEST(FieldEdgeEvidence, CostIsZeroOnTheEdgeAndSaturatesFarFromIt) {
  FieldEdgeConfig config;
  config.sigma_floor_m = 0.0;
  config.min_samples = 1;
  // Robot at the SPL centre facing +x: the edge 5.2 m ahead and 3.7 m to the left.
  const FieldEdgeEvidence evidence(edgeSamples({{5.2, 0.0}, {0.0, 3.7}}, 0.1), config);
  ASSERT_FALSE(evidence.empty());
  EXPECT_NEAR(evidence.meanCost(Pose2(0.0, 0.0, 0.0), 5.2, 3.7), 0.0, 1e-12);
  // 0.15 m further forward: the first sample is 0.15 m = 1.5 sigma too far (seen farther than
  // predicted: full weight), cost (1.5 / 3)^2; the second one is unchanged.
  EXPECT_NEAR(evidence.meanCost(Pose2(0.15, 0.0, 0.0), 5.2, 3.7), 0.5 * 0.25, 1e-9);
  // 0.15 m back: seen nearer than predicted, nearer_weight of that.
  EXPECT_NEAR(evidence.meanCost(Pose2(-0.15, 0.0, 0.0), 5.2, 3.7),
              0.5 * config.nearer_weight * 0.25, 1e-9);
  // Turned by 90 deg: both samples are 1.5 m off and saturate, the first seen farther (5.2 m
  // where the pose predicts 3.7 m), the second nearer.
  const double turned = 0.5 * (1.0 + config.nearer_weight);
  EXPECT_NEAR(evidence.meanCost(Pose2(0.0, 0.0, M_PI / 2), 5.2, 3.7), turned, 1e-9);
  EXPECT_NEAR(evidence.penaltyMetres(Pose2(0.0, 0.0, M_PI / 2), 5.2, 3.7), config.weight_m * turned,
              1e-9);
}

TEST(FieldEdgeEvidence, IgnoresBadSamplesAndTooFewOfThem) {
  const double nan = std::nan("");
  FieldEdgeConfig config;  // min_samples 4
  EXPECT_TRUE(FieldEdgeEvidence(edgeSamples({{5.2, 0.0}, {0.0, 3.7}}, 0.1), config).empty());
  const GroundPoints bad =
      edgeSamples({{nan, 1.0}, {0.0, 0.0}, {100.0, 0.0}, {5.2, 0.0}, {5.2, 0.1}, {5.2, -0.1}}, 0.1);
  EXPECT_TRUE(FieldEdgeEvidence(bad, config).empty());  // 3 usable samples
  GroundPoints negative_sigma = edgeSamples({{5.2, 0.0}, {5.2, 0.1}, {5.2, -0.1}, {5.2, 0.2}}, -1);
  EXPECT_TRUE(FieldEdgeEvidence(negative_sigma, config).empty());
  config.enabled = false;
  EXPECT_TRUE(
      FieldEdgeEvidence(edgeSamples({{5.2, 0.0}, {5.2, 0.1}, {5.2, -0.1}, {5.2, 0.2}}, 0.1), config)
          .empty());
}

/// A robot right in front hides the carpet's edge in every column: no pose explains the
/// samples, and the frame ignores them instead of charging every pose the same penalty.
TEST(FieldEdgeEvidence, AnEdgeThatNoCandidateExplainsIsIgnored) {
  const FieldModel field = makeStandardField("spl");
  GroundPoints frame =
      edgeSamples({{0.8, -0.2}, {0.8, -0.1}, {0.8, 0.0}, {0.8, 0.1}, {0.8, 0.2}}, 0.01);
  frame.visible_regions = {{{0.2, -1.0}, {2.0, -1.0}, {2.0, 1.0}, {0.2, 1.0}}};
  WeightedPoints points;
  for (double x = 0.5; x < 2.0; x += 0.05) {
    points.points.push_back({x, 0.5});
    points.weights.push_back(1.0);
  }
  VisibilityEvidence evidence(frame, points, NegativeEvidenceConfig{});
  ASSERT_FALSE(evidence.edgeEmpty());
  const std::vector<Pose2> centre_poses = {Pose2(0.0, 0.0, 0.0), Pose2(1.0, 1.0, 2.0)};
  EXPECT_GT(evidence.edgePenalty(centre_poses[0], field), 0.0);
  EXPECT_FALSE(evidence.keepEdgeIfAnyFits(centre_poses, field));
  EXPECT_TRUE(evidence.edgeEmpty());
  EXPECT_EQ(evidence.edgePenalty(centre_poses[0], field), 0.0);
  // 0.8 m from the east edge of the carpet (x = 5.2) facing it, the same samples fit.
  VisibilityEvidence fitting(frame, points, NegativeEvidenceConfig{});
  EXPECT_TRUE(fitting.keepEdgeIfAnyFits({Pose2(0.0, 0.0, 0.0), Pose2(4.4, 0.0, 0.0)}, field));
  EXPECT_FALSE(fitting.edgeEmpty());
}

/// The synthetic generator reports the carpet's edge where the geometry puts it (noise-free
/// here) and an occluder in the way as nearer.
TEST(FieldEdgeEvidence, SyntheticEdgeSamplesLieOnTheCarpetEdge) {
  const FieldModel field = makeStandardField("spl");
  SyntheticConfig config;
  config.view = viewModel("kid-wide");
  config.field_edge_sigma_px = 0.0;
  const Pose2 pose(1.0, -0.5, 0.3);
  const SyntheticFrame frame = generateFrame(field, pose, config);
  ASSERT_EQ(frame.ground.field_edge.size(), 24u);
  const FieldEdgeEvidence evidence(frame.ground, FieldEdgeConfig{});
  EXPECT_NEAR(evidence.meanCost(pose, field.outerHalfLength(), field.outerHalfWidth()), 0.0, 1e-9);
  for (const FieldEdgePoint& e : frame.ground.field_edge) {
    const Eigen::Vector2d p = pose.transform(e.p_robot);
    const double to_edge = std::min(field.outerHalfLength() - std::abs(p.x()),
                                    field.outerHalfWidth() - std::abs(p.y()));
    EXPECT_NEAR(to_edge, 0.0, 1e-9);
  }
}

/// A lone arc of the MSL centre circle seen from 1.8 m west of it (the halfway line is beyond
/// the 3 m view): the lines fit every rotation about the circle's centre; with the carpet's
/// edge the localizer finds the truth.
TEST(FieldEdgeEvidence, SettlesTheRotationAboutALoneCentreCircleArc) {
  const FieldModel field = makeStandardField("msl");
  SyntheticConfig config;
  config.view = viewModel("kid-wide");
  config.view.max_range_m = 3.0;
  config.field_edge_sigma_px = 1.0;
  const Pose2 truth(-3.8, -0.3, 0.1);  // looking at the circle's west side
  const SyntheticFrame frame = generateFrame(field, truth, config);
  ASSERT_TRUE(hasTwoDirections(frame));
  for (const VisibleFeature& v : frame.visible) ASSERT_NE(v.feature.kind, FeatureKind::kSegment);
  auto correct = [&](const std::vector<PoseHypothesis>& hs) {
    for (const PoseHypothesis& h : hs) {
      for (const Pose2& t : {truth, mirrored(truth)}) {
        if ((h.field_T_robot.translation() - t.translation()).norm() <= 0.10 &&
            std::abs(angleDifference(h.field_T_robot.theta, t.theta)) <= 3.0 * M_PI / 180.0) {
          return true;
        }
      }
    }
    return false;
  };
  const GlobalHoughLocalizer localizer(field);
  EXPECT_TRUE(correct(localizer.locate(frame.ground)));
  GroundPoints lines_only = frame.ground;
  lines_only.field_edge.clear();
  EXPECT_FALSE(correct(localizer.locate(lines_only)));
}

}  // namespace
}  // namespace houghloc
