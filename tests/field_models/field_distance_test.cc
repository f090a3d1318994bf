#include "field_models/field_distance.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>

#include "field_models/standard_fields.h"

namespace houghloc {
namespace {

/// Independent reference: the distance to points sampled every 0.5 mm along every painted
/// centre line (and over each dot), so it is within 0.25 mm above the exact value.
double sampledDistance(const FieldModel& f, const Eigen::Vector2d& p) {
  constexpr double kStep = 5e-4;
  double best = std::numeric_limits<double>::infinity();
  auto along = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / kStep)));
    for (int i = 0; i <= n; ++i) best = std::min(best, (a + (b - a) * i / n - p).norm());
  };
  for (const Segment2& s : f.segments) along(s.a, s.b);
  for (const Arc2& a : f.arcs) {
    const int n = static_cast<int>(std::ceil(a.radius * a.sweep_rad / kStep));
    for (int i = 0; i <= n; ++i) {
      best = std::min(best, (a.pointAt(a.start_rad + a.sweep_rad * i / n) - p).norm());
    }
  }
  for (const Mark& m : f.marks) {
    const double h = 0.5 * m.size;
    if (m.shape == MarkShape::kDot) {
      best = std::min(best, std::max(0.0, (p - m.center).norm() - h));
    } else {
      along(m.center - Eigen::Vector2d(h, 0), m.center + Eigen::Vector2d(h, 0));
      along(m.center - Eigen::Vector2d(0, h), m.center + Eigen::Vector2d(0, h));
    }
  }
  return best;
}

TEST(NearestFeatureTest, KnownPoints) {
  const FieldModel f = makeStandardField("spl");
  // 1 m right of the centre: the centre circle (r = 0.75) is 0.25 m away.
  NearestFeature n = nearestFeature(f, {1.0, 0.0});
  EXPECT_EQ(n.feature.kind, FeatureKind::kArc);
  EXPECT_EQ(n.feature.index, 0);
  EXPECT_NEAR(n.distance_m, 0.25, 1e-12);
  EXPECT_LT((n.closest_point - Eigen::Vector2d(0.75, 0.0)).norm(), 1e-12);
  // Near the opponent goal line (x = 4.5), 0.3 m before it and 0.4 m from the touch line.
  n = nearestFeature(f, {4.2, 2.6});
  ASSERT_EQ(n.feature.kind, FeatureKind::kSegment);
  const Segment2& s = f.segments[n.feature.index];
  EXPECT_EQ(s.a.x(), 4.5);
  EXPECT_EQ(s.b.x(), 4.5);
  EXPECT_NEAR(n.distance_m, 0.3, 1e-12);
  // Next to the opponent penalty mark (3.2, 0), a cross of 0.1 m.
  n = nearestFeature(f, {3.2, 0.2});
  EXPECT_EQ(n.feature.kind, FeatureKind::kMark);
  EXPECT_NEAR(n.distance_m, 0.15, 1e-12);
  EXPECT_EQ(describeFeature(n.feature), "marks[" + std::to_string(n.feature.index) + "]");
  EXPECT_EQ(nearestFeature(FieldModel{}, {0.0, 0.0}).feature.index, -1);
}

class NearestFeatureRandomTest : public ::testing::TestWithParam<std::string> {};

TEST_P(NearestFeatureRandomTest, MatchesSampledReference) {
  const FieldModel f = makeStandardField(GetParam());
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> x(-f.outerHalfLength(), f.outerHalfLength());
  std::uniform_real_distribution<double> y(-f.outerHalfWidth(), f.outerHalfWidth());
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector2d p(x(rng), y(rng));
    const NearestFeature n = nearestFeature(f, p);
    const double reference = sampledDistance(f, p);
    EXPECT_LE(n.distance_m, reference + 1e-12) << p.transpose();
    EXPECT_GE(n.distance_m, reference - 2.5e-4) << p.transpose();
    EXPECT_NEAR((n.closest_point - p).norm(), n.distance_m, 1e-12);
  }
}

// The search that the precomputed maps use gives nearestFeature()'s answer bit for bit: on a
// grid walked row by row (its warm start), at random points, on ties (the field's symmetry puts
// many grid nodes at equal distance from two lines) and at points that are not finite.
TEST_P(NearestFeatureRandomTest, SearchEqualsNearestFeatureBitForBit) {
  FieldModel f = makeStandardField(GetParam());
  // A partial arc, a dot and a cross of their own, whatever the standard field has.
  f.arcs.push_back(Arc2{{1.0, 1.0}, 0.4, 0.3, 2.0});
  f.marks.push_back(Mark{{-2.0, 1.5}, 0.1, MarkShape::kDot});
  f.marks.push_back(Mark{{-2.5, -1.0}, 0.12, MarkShape::kCross});
  NearestFeatureSearch search(f);
  auto expectSame = [&](const Eigen::Vector2d& p) {
    const NearestFeature want = nearestFeature(f, p), got = search.nearest(p);
    ASSERT_EQ(got.feature.kind, want.feature.kind) << p.transpose();
    ASSERT_EQ(got.feature.index, want.feature.index) << p.transpose();
    // Bit for bit (NaN compares unequal to itself, so compare the bytes).
    ASSERT_EQ(std::memcmp(&got.distance_m, &want.distance_m, sizeof(double)), 0) << p.transpose();
    ASSERT_EQ(std::memcmp(got.closest_point.data(), want.closest_point.data(), 2 * sizeof(double)),
              0)
        << p.transpose();
  };
  const double hx = f.outerHalfLength() + 0.5, hy = f.outerHalfWidth() + 0.5;
  int ties = 0;
  for (double y = -hy; y <= hy; y += 0.05) {
    for (double x = -hx; x <= hx; x += 0.05) {
      expectSame({x, y});
      const Eigen::Vector2d mirrored(-x, y);  // equidistant from both halves' lines
      expectSame(mirrored);
      ties += nearestFeature(f, {x, y}).distance_m == nearestFeature(f, mirrored).distance_m;
    }
  }
  EXPECT_GT(ties, 100);
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> x(-hx - 2.0, hx + 2.0), y(-hy - 2.0, hy + 2.0);
  for (int i = 0; i < 20000; ++i) expectSame({x(rng), y(rng)});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(nan, 0.0), Eigen::Vector2d(0.0, inf),
                                   Eigen::Vector2d(1e300, -1e300), Eigen::Vector2d(0.0, 0.0)}) {
    expectSame(p);
  }
  EXPECT_EQ(NearestFeatureSearch(FieldModel{}).nearest({0.0, 0.0}).feature.index, -1);
}

INSTANTIATE_TEST_SUITE_P(AllFields, NearestFeatureRandomTest,
                         ::testing::ValuesIn(standardFieldNames()));

}  // namespace
}  // namespace houghloc
