#include "localization/tracked_hypotheses.h"

#include <gtest/gtest.h>

namespace houghloc {
namespace {

TrackedHypothesis make(double x, double y, double theta, double weight, int id,
                       double variance = 1e-4) {
  TrackedHypothesis h;
  h.pose.mean = Pose2(x, y, theta);
  h.pose.covariance = Eigen::Matrix3d::Identity() * variance;
  h.pose.weight = weight;
  h.id = id;
  return h;
}

TEST(TrackedHypotheses, MergeIsMomentMatched) {
  std::vector<TrackedHypothesis> set = {make(0.0, 0.0, 0.0, 0.75, 0),
                                        make(0.04, 0.0, 0.0, 0.25, 1)};
  mergeConverged(TrackedSetConfig{}, &set);
  ASSERT_EQ(set.size(), 1u);
  EXPECT_EQ(set[0].id, 0);  // the stronger keeps its id
  EXPECT_NEAR(set[0].pose.weight, 1.0, 1e-12);
  EXPECT_NEAR(set[0].pose.mean.x, 0.01, 1e-12);
  // 0.75 (1e-4 + 0.01^2) + 0.25 (1e-4 + 0.03^2)
  EXPECT_NEAR(set[0].pose.covariance(0, 0), 4e-4, 1e-12);
  EXPECT_NEAR(set[0].pose.covariance(1, 1), 1e-4, 1e-12);
}

TEST(TrackedHypotheses, MergeAveragesHeadingsAcrossPi) {
  const GaussianPose m =
      mergeGaussians(make(0, 0, M_PI - 0.01, 0.5, 0).pose, make(0, 0, -M_PI + 0.01, 0.5, 1).pose);
  EXPECT_NEAR(std::abs(m.mean.theta), M_PI, 1e-9);
}

TEST(TrackedHypotheses, DistinctOrMirroredPosesAreNotMerged) {
  std::vector<TrackedHypothesis> set = {make(1.0, 0.5, 0.2, 0.5, 0, 0.04),
                                        make(-1.0, -0.5, 0.2 + M_PI, 0.5, 1, 0.04),
                                        make(1.5, 0.5, 0.2, 0.5, 2, 0.04)};
  mergeConverged(TrackedSetConfig{}, &set);  // 0.5 m apart: beyond merge_max_distance_m
  EXPECT_EQ(set.size(), 3u);
  EXPECT_TRUE(areMirrors(set[0].pose.mean, set[1].pose.mean, 0.01, 0.01));
}

TEST(TrackedHypotheses, MahalanobisMergeWithinLimits) {
  std::vector<TrackedHypothesis> set = {make(0.0, 0.0, 0.0, 0.5, 0, 0.01),
                                        make(0.2, 0.0, 0.0, 0.5, 1, 0.01)};
  EXPECT_NEAR(mahalanobisSquared(set[0].pose, set[1].pose), 0.04 / 0.02, 1e-9);
  mergeConverged(TrackedSetConfig{}, &set);
  EXPECT_EQ(set.size(), 1u);
}

TEST(TrackedHypotheses, PruneDropsWeakAndKeepsAtMostMax) {
  std::vector<TrackedHypothesis> set;
  for (int i = 0; i < 20; ++i) set.push_back(make(0.5 * i, 0, 0, 1.0, i));
  set.push_back(make(-3, 0, 0, 1e-5, 99));
  TrackedSetConfig config;
  config.max_hypotheses = 12;
  pruneWeak(config, &set);
  ASSERT_EQ(set.size(), 12u);
  double sum = 0.0;
  for (const auto& h : set) {
    EXPECT_NE(h.id, 99);
    sum += h.pose.weight;
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_EQ(set.front().id, 0);  // ties broken by id: deterministic
}

TEST(TrackedHypotheses, NormalizeRepairsNonFiniteWeights) {
  std::vector<TrackedHypothesis> set = {make(0, 0, 0, std::nan(""), 0), make(1, 0, 0, -1.0, 1)};
  normalizeTrackedWeights(&set);
  EXPECT_NEAR(set[0].pose.weight, 0.5, 1e-12);
  EXPECT_NEAR(set[1].pose.weight, 0.5, 1e-12);
}

TEST(GaussianPose, MirrorFlipsThePositionHeadingCorrelations) {
  GaussianPose g;
  g.mean = Pose2(1.0, 2.0, 0.5);
  g.covariance << 0.1, 0.01, 0.02, 0.01, 0.2, 0.03, 0.02, 0.03, 0.3;
  const GaussianPose m = mirrored(g);
  EXPECT_NEAR(m.mean.x, -1.0, 1e-12);
  EXPECT_NEAR(m.mean.y, -2.0, 1e-12);
  EXPECT_NEAR(m.mean.theta, 0.5 - M_PI, 1e-12);
  EXPECT_NEAR(m.covariance(0, 1), 0.01, 1e-12);
  EXPECT_NEAR(m.covariance(0, 2), -0.02, 1e-12);
  EXPECT_NEAR(m.covariance(1, 2), -0.03, 1e-12);
  EXPECT_NEAR(m.covariance(2, 2), 0.3, 1e-12);
}

}  // namespace
}  // namespace houghloc
