// The speed-ups of issue 6 must not change results: each fast path against the plain
// computation it replaces, bit for bit where the code promises it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "field_models/distance_grid.h"
#include "field_models/field_distance.h"
#include "field_models/standard_fields.h"
#include "localization/field_edge_evidence.h"
#include "localization/hough_transform.h"
#include "localization/map_signature.h"
#include "localization/orientation_search.h"
#include "localization/pose_refinement.h"
#include "localization/pose_scoring.h"

namespace houghloc {
namespace {

class FastPathsTest : public ::testing::TestWithParam<const char*> {};

TEST_P(FastPathsTest, DistanceBelowIsTheDistanceOrABoundAboveTheLimit) {
  const FieldModel field = makeStandardField(GetParam());
  const DistanceGrid grid(field);
  std::mt19937 rng(5);
  // Beyond the grid too (its margin is 0.5 m past the carpet).
  std::uniform_real_distribution<double> x(-field.outerHalfLength() - 1.0,
                                           field.outerHalfLength() + 1.0);
  std::uniform_real_distribution<double> y(-field.outerHalfWidth() - 1.0,
                                           field.outerHalfWidth() + 1.0);
  int below = 0, skipped = 0;
  for (int i = 0; i < 50000; ++i) {
    const Eigen::Vector2d p(x(rng), y(rng));
    const double limit = i % 2 ? 0.15 : 0.4;
    const double d = grid.distance(p), fast = grid.distanceBelow(p, limit);
    if (d < limit) {
      ASSERT_EQ(fast, d) << p.transpose();  // bit for bit
      ++below;
    } else {
      ASSERT_GE(fast, limit) << p.transpose();
      ASSERT_LE(fast, d) << p.transpose();
      skipped += fast != d;
    }
    // The lower bound holds for the exact distance, not only for the interpolated one.
    ASSERT_LE(grid.lowerBound(p), nearestFeature(field, p).distance_m) << p.transpose();
  }
  EXPECT_GT(below, 1000);
  EXPECT_GT(skipped, 10000);  // the block map answers most far points
}

TEST_P(FastPathsTest, RefinementWithTheGridSkipIsBitIdentical) {
  const FieldModel field = makeStandardField(GetParam());
  const MapSignature map(field);
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    // Points on the map seen from a pose near the field's corner region, plus clutter.
    const Pose2 truth(u(rng) * field.outerHalfLength() * 0.7, u(rng) * field.outerHalfWidth() * 0.7,
                      M_PI * u(rng));
    const WeightedPoints samples = sampleMapLines(field, 0.05, true);
    WeightedPoints points;
    const Pose2 robot_T_field = truth.inverse();
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const Eigen::Vector2d p = robot_T_field.transform(samples.points[i]);
      if (p.norm() > 4.0 || p.x() < 0.0) continue;
      points.points.push_back(p + Eigen::Vector2d(noise(rng), noise(rng)));
      points.weights.push_back(1.0);
    }
    for (int k = 0; k < 20; ++k) {
      points.points.push_back(Eigen::Vector2d(4.0 * std::abs(u(rng)), 3.0 * u(rng)));
      points.weights.push_back(0.5);
    }
    const Pose2 start(truth.x + 0.15 * u(rng), truth.y + 0.15 * u(rng),
                      truth.theta + 0.05 * u(rng));
    RefinementConfig config;
    const Eigen::Vector2d frozen =
        trial % 3 == 0 ? Eigen::Vector2d(1.0, 0.0) : Eigen::Vector2d(0, 0);
    const RefinementResult plain = refinePose(points, start, map.features(), config, frozen);
    const RefinementResult fast = refinePose(points, start, map, config, frozen);
    EXPECT_EQ(plain.field_T_robot.x, fast.field_T_robot.x);
    EXPECT_EQ(plain.field_T_robot.y, fast.field_T_robot.y);
    EXPECT_EQ(plain.field_T_robot.theta, fast.field_T_robot.theta);
    EXPECT_EQ(plain.rms_m, fast.rms_m);
    EXPECT_EQ(plain.inlier_weight, fast.inlier_weight);
    EXPECT_TRUE((plain.covariance.array() == fast.covariance.array()).all());
    const Pose2 mean = refinePoseMean(points, start, map, config, frozen);
    EXPECT_EQ(plain.field_T_robot.x, mean.x);
    EXPECT_EQ(plain.field_T_robot.theta, mean.theta);
  }
}

TEST_P(FastPathsTest, ScoringATranslationScanEqualsScoringEachPose) {
  const FieldModel field = makeStandardField(GetParam());
  const DistanceGrid grid(field);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  WeightedPoints points;
  for (int i = 0; i < 90; ++i) {  // more than one batch of the scorer
    points.points.push_back(Eigen::Vector2d(4.0 * std::abs(u(rng)), 3.0 * u(rng)));
    points.weights.push_back(0.5 + std::abs(u(rng)));
  }
  const ScoringConfig config;
  for (double theta : {0.3, -2.9, 3.5, 7.0}) {  // also headings that Pose2 normalises
    std::vector<Eigen::Vector2d> ts;
    for (double s = -field.outerHalfLength(); s <= field.outerHalfLength(); s += 0.1) {
      ts.push_back(Eigen::Vector2d(s, 0.37 * s + 0.2 * u(rng)));
    }
    const std::vector<PoseScore> scan = scoreTranslations(points, theta, ts, grid, config);
    ASSERT_EQ(scan.size(), ts.size());
    double best = 0.0;
    for (std::size_t k = 0; k < ts.size(); ++k) {
      const PoseScore one = scorePose(points, Pose2(ts[k].x(), ts[k].y(), theta), grid, config);
      ASSERT_EQ(scan[k].score, one.score) << k;
      ASSERT_EQ(scan[k].inlier_share, one.inlier_share) << k;
      best = std::max(best, one.score);
    }
    EXPECT_GT(best, 0.0);  // some poses put points on lines
  }
}

TEST_P(FastPathsTest, MovedLowerBoundAndFarMoveHoldOnAndOffTheGrid) {
  const FieldModel field = makeStandardField(GetParam());
  const DistanceGrid grid(field);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // From points on the grid and beyond it (the grid ends 0.5 m past the carpet).
  const double hx = field.outerHalfLength() + 2.0, hy = field.outerHalfWidth() + 2.0;
  int useful = 0, off_grid = 0, skipping = 0;
  for (int i = 0; i < 100000; ++i) {
    const Eigen::Vector2d q(hx * u(rng), hy * u(rng));
    const double limit = i % 2 ? 0.15 : 0.4;
    const double seen = grid.distanceBelow(q, limit);
    // Short moves (a scan's steps) and long ones, in any direction.
    const double moved = (i % 3 ? 0.3 : 3.0) * std::abs(u(rng));
    const double angle = M_PI * u(rng);
    const Eigen::Vector2d step = moved * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    const Eigen::Vector2d q2 = q + step;
    const double bound =
        grid.movedLowerBound(q, seen, step.cwiseAbs().sum() + 1e-9, step.norm() + 1e-9);
    ASSERT_LE(bound, grid.distance(q2)) << q.transpose() << " -> " << q2.transpose();
    if (bound >= limit) {
      ASSERT_GE(grid.distanceBelow(q2, limit), limit);
      ++useful;
      off_grid += !grid.onGrid(q);
    }
    // farMove along the same direction, scaled as scoreAlongLine scales a scan's against
    // rounding: every move up to it keeps the bound at or above the limit, one 1e-6 longer not.
    const double l1 = (std::abs(std::cos(angle)) + std::abs(std::sin(angle))) * (1.0 + 1e-12);
    const double length = 1.0 + 1e-12;
    const bool on_grid = grid.onGrid(q);
    const double far = grid.farMove(on_grid, seen, limit, l1, length, 1e-9);
    const auto boundAfter = [&](double t) {
      return grid.movedLowerBound(on_grid, seen, t * l1 + 1e-9, t * length + 1e-9);
    };
    if (far < 0.0) {
      ASSERT_LT(boundAfter(0.0), limit + 1e-6) << q.transpose();
      continue;
    }
    for (const double t : {0.0, 0.5 * far, far}) ASSERT_GE(boundAfter(t), limit) << q.transpose();
    ASSERT_LT(boundAfter(far + 1e-6), limit) << q.transpose();
    ++skipping;
  }
  EXPECT_GT(useful, 10000);  // the bound is tight enough to skip many positions
  EXPECT_GT(off_grid, 1000);
  EXPECT_GT(skipping, 10000);
}

TEST_P(FastPathsTest, ScoringAlongALineEqualsScoringEachPose) {
  const FieldModel field = makeStandardField(GetParam());
  const DistanceGrid grid(field);
  std::mt19937 rng(29);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // Map points seen from a pose (so that the scan passes along lines) plus clutter.
  const Pose2 truth(1.0, -0.5, 0.4);  // the centre circle and halfway line in view
  const WeightedPoints samples = sampleMapLines(field, 0.05, true);
  WeightedPoints points;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Eigen::Vector2d p = truth.inverse().transform(samples.points[i]);
    if (p.norm() > 5.0 || p.x() < 0.0) continue;
    points.points.push_back(p + Eigen::Vector2d(noise(rng), noise(rng)));
    points.weights.push_back(0.5 + std::abs(u(rng)));
  }
  for (int k = 0; k < 30; ++k) {
    points.points.push_back(Eigen::Vector2d(6.0 * std::abs(u(rng)), 4.0 * u(rng)));
    points.weights.push_back(0.5);
  }
  ASSERT_GT(points.size(), 60u);
  const ScoringConfig config;
  int on_lines = 0;
  // Along the field's axes and diagonally; headings that Pose2 normalises; scans that leave the
  // grid (the carpet plus 0.5 m) at both ends.
  for (double along : {0.0, M_PI / 2.0, 0.7}) {
    for (double theta : {truth.theta, truth.theta + 2.0 * M_PI, -2.9}) {
      const Eigen::Vector2d dir(std::cos(along), std::sin(along));
      std::vector<double> s_values;
      for (double s = -field.outerHalfLength() - 2.0; s <= field.outerHalfLength() + 2.0; s += 0.1)
        s_values.push_back(s);
      const Eigen::Vector2d t0 = truth.translation() + 0.01 * Eigen::Vector2d(u(rng), u(rng));
      const std::vector<double> scan =
          scoreAlongLine(points, theta, t0, dir, s_values, grid, config);
      ASSERT_EQ(scan.size(), s_values.size());
      for (std::size_t k = 0; k < s_values.size(); ++k) {
        const Eigen::Vector2d t = t0 + s_values[k] * dir;
        const double one = scorePose(points, Pose2(t.x(), t.y(), theta), grid, config).score;
        ASSERT_EQ(scan[k], one) << along << " " << theta << " " << k;  // bit for bit
        on_lines += one > 0.3 * points.totalWeight();
      }
      // The early stop: a scan asked to reach its own best score runs to the end and gives the
      // same numbers; asked for a little more, it stops (returns nothing).
      const double best = *std::max_element(scan.begin(), scan.end());
      EXPECT_EQ(scoreAlongLine(points, theta, t0, dir, s_values, grid, config, best), scan);
      EXPECT_TRUE(scoreAlongLine(points, theta, t0, dir, s_values, grid, config,
                                 best + 1e-6 * points.totalWeight())
                      .empty());
    }
  }
  EXPECT_GT(on_lines, 10);  // some positions put many points on lines
}

// The bucketed visit is a superset of the samples inside the box, on the field, beside it,
// far off it, and for a NaN box (poses far off the field reach it: tests/fuzz localizer).
TEST_P(FastPathsTest, EvidenceBucketsVisitEverySampleInTheBoxAndNoneOfAMissingBox) {
  const MapSignature map(makeStandardField(GetParam()));
  const auto& samples = map.evidenceSamples();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> corner(-60.0, 60.0), size(0.0, 20.0);
  for (int i = 0; i < 3000; ++i) {
    const Eigen::Vector2d lo(corner(rng), corner(rng));
    const Eigen::Vector2d hi = lo + Eigen::Vector2d(size(rng), size(rng));
    std::size_t inside = 0, visited_inside = 0, visited = 0;
    for (const auto& p : samples)
      inside += (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
    map.forEachEvidenceSample(lo, hi, [&](const Eigen::Vector2d& p) {
      ++visited;
      visited_inside += (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
    });
    ASSERT_EQ(visited_inside, inside) << lo.transpose() << " .. " << hi.transpose();
    ASSERT_LE(visited, samples.size());
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int visited = 0;
  map.forEachEvidenceSample(Eigen::Vector2d(nan, 0.0), Eigen::Vector2d(1.0, 1.0),
                            [&](const Eigen::Vector2d&) { ++visited; });
  map.forEachEvidenceSample(Eigen::Vector2d(-1e300, -1e300), Eigen::Vector2d(-1e299, -1e299),
                            [&](const Eigen::Vector2d&) { ++visited; });
  EXPECT_EQ(visited, 0);
  map.forEachEvidenceSample(Eigen::Vector2d(-1e300, -1e300), Eigen::Vector2d(1e300, 1e300),
                            [&](const Eigen::Vector2d&) { ++visited; });
  EXPECT_EQ(visited, static_cast<int>(samples.size()));
}

TEST_P(FastPathsTest, FieldEdgeCostInBlocksEqualsTheCostSampleBySample) {
  const FieldModel field = makeStandardField(GetParam());
  const double hx = field.outerHalfLength(), hy = field.outerHalfWidth();
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  FieldEdgeConfig config;
  config.sigma_floor_m = 0.15;
  config.min_samples = 1;
  // 70 samples: two full blocks of meanCost's 32 and a partial one; axis-parallel rays too.
  GroundPoints frame;
  for (int i = 0; i < 70; ++i) {
    const double bearing = i % 10 == 0 ? M_PI / 2 * (i / 10 % 4) : M_PI * u(rng);
    const double range = 1.0 + 12.0 * std::abs(u(rng));
    frame.field_edge.push_back(
        {range * Eigen::Vector2d(std::cos(bearing), std::sin(bearing)), 0.3 * std::abs(u(rng)), 0});
  }
  const FieldEdgeEvidence evidence(frame, config);
  ASSERT_FALSE(evidence.empty());
  for (int trial = 0; trial < 2000; ++trial) {
    // On the carpet, near its edge, and off it.
    const Pose2 pose(1.2 * hx * u(rng), 1.2 * hy * u(rng), M_PI * u(rng));
    // The plain computation: one sample after the other, as before the blocks.
    const bool off = !(std::abs(pose.x) <= hx && std::abs(pose.y) <= hy);
    const double c = std::cos(pose.theta), s = std::sin(pose.theta);
    double sum = 0.0;
    for (const FieldEdgePoint& e : frame.field_edge) {
      const double range = e.p_robot.norm();
      const Eigen::Vector2d direction = e.p_robot / range;
      const double inv_sigma =
          1.0 / (config.clip_sigmas * std::hypot(e.range_sigma_m, config.sigma_floor_m));
      const double dx = c * direction.x() - s * direction.y();
      const double dy = s * direction.x() + c * direction.y();
      const double to_x = (std::copysign(hx, dx) - pose.x) / dx;
      const double to_y = (std::copysign(hy, dy) - pose.y) / dy;
      const double predicted = off ? 0.0 : std::min(to_x, to_y);
      const double error = std::min(1.0, std::abs(range - predicted) * inv_sigma);
      sum += (range < predicted ? config.nearer_weight : 1.0) * error * error;
    }
    const double plain = sum / static_cast<double>(frame.field_edge.size());
    ASSERT_EQ(evidence.meanCost(pose, hx, hy), plain) << trial;  // bit for bit
  }
}

INSTANTIATE_TEST_SUITE_P(Fields, FastPathsTest, ::testing::Values("spl", "msl"));

TEST(FastAngleTest, NormalizeAngleEqualsTheGeneralWrap) {
  // The in-range fast path against std::remainder's wrap, at the ends of the range, just beyond
  // them and at random, bit for bit.
  std::vector<double> angles = {0.0,
                                -0.0,
                                M_PI,
                                -M_PI,
                                std::nextafter(M_PI, 0.0),
                                std::nextafter(M_PI, 4.0),
                                std::nextafter(-M_PI, 0.0),
                                std::nextafter(-M_PI, -4.0),
                                2.0 * M_PI,
                                -2.0 * M_PI,
                                3.0 * M_PI,
                                1e-300,
                                std::numeric_limits<double>::infinity(),
                                std::numeric_limits<double>::quiet_NaN()};
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-4.0 * M_PI, 4.0 * M_PI);
  for (int i = 0; i < 100000; ++i) angles.push_back(i % 2 ? u(rng) : u(rng) / 4.0);
  for (const double a : angles) {
    const double fast = normalizeAngle(a), general = wrapAngle(a);
    if (std::isnan(general)) {
      ASSERT_TRUE(std::isnan(fast)) << a;
    } else {
      ASSERT_EQ(std::signbit(fast), std::signbit(general)) << a;
      ASSERT_EQ(fast, general) << a;
    }
    if (std::isfinite(a)) {
      ASSERT_TRUE(fast > -M_PI && fast <= M_PI) << a;
    }
  }
}

TEST(FastHoughTest, AddPointsEqualsAddPointOneByOne) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  WeightedPoints points;
  for (int i = 0; i < 400; ++i) {
    points.points.push_back(Eigen::Vector2d(u(rng), u(rng)));
    points.weights.push_back(0.1 + std::abs(u(rng)));
  }
  // Beyond rho_max (the slow vote path) and invalid input (skipped by both).
  points.points.push_back(Eigen::Vector2d(9.0, -8.0));
  points.weights.push_back(1.0);
  points.points.push_back(Eigen::Vector2d(std::numeric_limits<double>::quiet_NaN(), 1.0));
  points.weights.push_back(1.0);
  points.points.push_back(Eigen::Vector2d(1.0, 1.0));
  points.weights.push_back(std::numeric_limits<double>::infinity());
  HoughTransform batch(HoughConfig{}, 6.0), single(HoughConfig{}, 6.0);
  batch.addPoints(points);
  for (std::size_t k = 0; k < points.size(); ++k)
    single.addPoint(points.points[k], points.weights[k]);
  for (int c = 0; c < batch.numTheta(); ++c) {
    for (int r = 0; r < batch.numRho(); ++r)
      ASSERT_EQ(batch.at(c, r), single.at(c, r)) << c << " " << r;
  }
}

// Step 2's sums, written for speed (all shifts term by term; four columns side by side), against
// the plain loops: the same terms in the same order, so the same bits. 179 columns leave a
// remainder after the groups of four.
TEST(FastHoughTest, OrientationSumsEqualThePlainLoops) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  WeightedPoints points;
  for (int i = 0; i < 300; ++i) {
    const double t = u(rng);  // two lines and clutter
    points.points.push_back(i % 3 == 0   ? Eigen::Vector2d(t, 1.5)
                            : i % 3 == 1 ? Eigen::Vector2d(2.0, t)
                                         : Eigen::Vector2d(u(rng), u(rng)));
    points.weights.push_back(0.2 + std::abs(u(rng)));
  }
  for (int columns : {180, 179}) {
    HoughTransform transform(HoughConfig{M_PI / columns, 0.03}, 6.0);
    transform.addPoints(points);
    ASSERT_EQ(transform.numTheta(), columns);
    std::vector<double> plain(columns);
    for (int c = 0; c < columns; ++c) {
      double sum = 0.0;
      for (int r = 0; r < transform.numRho(); ++r) {
        sum += static_cast<double>(transform.at(c, r)) * transform.at(c, r);
      }
      plain[c] = sum;
    }
    // orientationProfile then centres and scales: do the same to the plain sums.
    double mean = 0.0, norm = 0.0;
    for (double v : plain) mean += v;
    mean /= columns;
    for (double& v : plain) {
      v -= mean;
      norm += v * v;
    }
    for (double& v : plain) v /= std::sqrt(norm);
    const std::vector<double> profile = orientationProfile(transform);
    ASSERT_EQ(profile.size(), plain.size());
    for (int c = 0; c < columns; ++c) ASSERT_EQ(profile[c], plain[c]) << c;  // bit for bit

    std::vector<double> m(columns);
    for (double& v : m) v = u(rng);
    const std::vector<double> fast = circularCorrelation(profile, m);
    ASSERT_EQ(fast.size(), m.size());
    for (int k = 0; k < columns; ++k) {
      double sum = 0.0;
      for (int i = 0; i < columns; ++i) sum += profile[i] * m[(i + k) % columns];
      ASSERT_EQ(fast[k], sum) << k;
    }
  }
}

}  // namespace
}  // namespace houghloc
