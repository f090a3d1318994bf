#include "field_models/field_distance.h"

#include <gtest/gtest.h>

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

INSTANTIATE_TEST_SUITE_P(AllFields, NearestFeatureRandomTest,
                         ::testing::ValuesIn(standardFieldNames()));

}  // namespace
}  // namespace houghloc
