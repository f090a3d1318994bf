// Paper steps 1-3 against hand-computed cases (DESIGN Appendix A).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "field_models/angles.h"
#include "field_models/standard_fields.h"
#include "localization/hough_transform.h"
#include "localization/map_signature.h"
#include "localization/orientation_search.h"
#include "localization/translation_search.h"

namespace houghloc {
namespace {

/// Points every `spacing` along the segment a-b, weight 1.
void addLine(WeightedPoints& pts, Eigen::Vector2d a, Eigen::Vector2d b, double spacing = 0.05) {
  const int n = static_cast<int>((b - a).norm() / spacing);
  for (int i = 0; i <= n; ++i) {
    pts.points.push_back(a + (b - a) * (static_cast<double>(i) / n));
    pts.weights.push_back(1.0);
  }
}

int argmax(const float* v, int n) { return static_cast<int>(std::max_element(v, v + n) - v); }

TEST(HoughTransform, LineAlongYPeaksAtThetaZeroAndItsRho) {
  WeightedPoints pts;
  addLine(pts, {1.2, -1.0}, {1.2, 1.0});  // x = 1.2: normal theta = 0, rho = 1.2
  HoughTransform ht(HoughConfig{}, 3.0);
  ht.addPoints(pts);
  ASSERT_EQ(ht.numTheta(), 180);
  const int row = argmax(ht.column(0), ht.numRho());
  EXPECT_NEAR(ht.rho(row), 1.2, 0.015);
  // Every vote lands in the column: the column sums to the point weight.
  double sum = 0.0;
  for (int j = 0; j < ht.numRho(); ++j) sum += ht.at(0, j);
  EXPECT_NEAR(sum, pts.totalWeight(), 1e-3);
  // The peak column at 0 holds all the weight in (at most) two rows; at 90 deg it is spread.
  EXPECT_GT(ht.at(0, row), 0.5 * pts.totalWeight());
  EXPECT_LT(*std::max_element(ht.column(90), ht.column(90) + ht.numRho()), 3.0f);
}

TEST(HoughTransform, WeightsScaleTheVotes) {
  HoughTransform ht(HoughConfig{}, 2.0);
  ht.addPoint({0.0, 0.9}, 2.5);
  double sum = 0.0;
  for (int j = 0; j < ht.numRho(); ++j) sum += ht.at(90, j);
  EXPECT_NEAR(sum, 2.5, 1e-5);
  EXPECT_NEAR(ht.rho(argmax(ht.column(90), ht.numRho())), 0.9, 0.015);
}

TEST(HoughTransform, ThetaWrapsAcrossPiWithNegatedRho) {
  // A line whose normal points at -10 deg with rho +1 is stored at theta 170 deg, rho -1.
  const Eigen::Vector2d n(std::cos(-10 * kDeg), std::sin(-10 * kDeg));
  const Eigen::Vector2d u(-n.y(), n.x());
  WeightedPoints pts;
  addLine(pts, n - 1.5 * u, n + 1.5 * u);
  HoughTransform ht(HoughConfig{}, 3.0);
  ht.addPoints(pts);
  const int column = 170;
  const int row = argmax(ht.column(column), ht.numRho());
  EXPECT_NEAR(ht.rho(row), -1.0, 0.02);
  EXPECT_GT(ht.at(column, row), 0.4 * pts.totalWeight());
  // houghColumn at the unwrapped angle is the mirrored column.
  const std::vector<float> col = houghColumn(pts, -10 * kDeg, 0.03, 3.0);
  const int centre = (static_cast<int>(col.size()) - 1) / 2;
  EXPECT_EQ(argmax(col.data(), static_cast<int>(col.size())) - centre, centre - row);
}

TEST(OrientationSearch, CircularCorrelationFindsTheShift) {
  std::vector<double> h(180, 0.0), m(180, 0.0);
  h[10] = 1.0;
  m[40] = 1.0;  // m(theta + 30) = h(theta)
  const std::vector<double> c = circularCorrelation(h, m);
  EXPECT_EQ(std::max_element(c.begin(), c.end()) - c.begin(), 30);
  h[10] = 0.0;
  h[170] = 1.0;  // wraps: 170 + 50 = 220 = 40 (mod 180)
  const std::vector<double> w = circularCorrelation(h, m);
  EXPECT_EQ(std::max_element(w.begin(), w.end()) - w.begin(), 50);
}

TEST(OrientationSearch, FlatProfileOfOnePointGivesNoNaN) {
  HoughTransform ht(HoughConfig{}, 1.0);
  const std::vector<double> h = orientationProfile(ht);  // empty transform
  for (double v : h) EXPECT_EQ(v, 0.0);
}

TEST(OrientationSearch, TwoPerpendicularLinesGiveTheHeadingModuloQuarterTurns) {
  // Robot heading 30 deg in the field; it sees two perpendicular lines (a field corner).
  const double theta_r = 30 * kDeg;
  const Eigen::Rotation2Dd robot_R_field(-theta_r);
  WeightedPoints pts;
  const Eigen::Vector2d corner = robot_R_field * Eigen::Vector2d(2.0, 1.0);
  addLine(pts, corner, corner + robot_R_field * Eigen::Vector2d(-2.0, 0.0));
  addLine(pts, corner, corner + robot_R_field * Eigen::Vector2d(0.0, -1.5));
  HoughTransform ht(HoughConfig{}, 4.0);
  ht.addPoints(pts);
  MapSignature map(makeStandardField("spl"));
  const auto candidates =
      findOrientationCandidates(orientationProfile(ht), map.profile(), OrientationConfig{});
  ASSERT_GE(candidates.size(), 4u);
  // The field's profile has period pi/2, so 30, 120, -60, -150 deg are all maxima.
  for (double expected : {30.0, 120.0, -60.0, -150.0}) {
    double best = 1e9;
    for (const auto& c : candidates) {
      best = std::min(best, std::abs(std::remainder(c.theta_rad - expected * kDeg, 2 * M_PI)));
    }
    EXPECT_LT(best, 0.6 * kDeg) << expected;
  }
  // Every candidate comes with its pi twin.
  for (const auto& c : candidates) {
    bool twin = false;
    for (const auto& o : candidates) {
      twin |= std::abs(std::remainder(o.theta_rad - c.theta_rad - M_PI, 2 * M_PI)) < 1e-9;
    }
    EXPECT_TRUE(twin);
  }
}

TEST(TranslationSearch, ColumnCorrelationOfHandMadeColumns) {
  std::vector<float> sensor(11, 0.0f), mask(21, 0.0f);
  sensor[5 + 2] = 4.0f;  // a sensor line at rho = +2 rows
  mask[10 + 7] = 1.0f;   // a map line at rho = +7 rows
  mask[10 - 3] = 1.0f;   // and one at -3 rows
  const std::vector<double> c = columnCorrelation(sensor, mask, 6);
  ASSERT_EQ(c.size(), 13u);
  EXPECT_DOUBLE_EQ(c[6 + 5], 4.0);  // d = 7 - 2
  EXPECT_DOUBLE_EQ(c[6 - 5], 4.0);  // d = -3 - 2
  EXPECT_DOUBLE_EQ(c[6], 0.0);
}

TEST(TranslationSearch, TwoPerpendicularLinesAtKnownOffsets) {
  // Robot at (1.0, 0.5), heading 0, sees the penalty area front line x = 2.85 and the penalty
  // area side y = 2.0 (SPL): d = T_x = 1.0 along theta_mu = 0, d = T_y = 0.5 along 90 deg.
  const FieldModel field = makeStandardField("spl");
  MapSignature map(field);
  WeightedPoints pts;
  addLine(pts, {1.85, -0.5}, {1.85, 1.5}, 0.04);
  addLine(pts, {1.85, 1.5}, {3.45, 1.5}, 0.04);
  for (int k = 0; k < static_cast<int>(map.dominantDirections().size()); ++k) {
    const double theta_mu = map.dominantDirections()[k];
    const double expected = std::abs(theta_mu) < 0.1 ? 1.0 : 0.5;
    const auto constraints = findTranslationConstraints(pts, map, k, 0.0, TranslationConfig{});
    ASSERT_FALSE(constraints.empty());
    double best = 1e9;
    for (const auto& c : constraints) best = std::min(best, std::abs(c.d_m - expected));
    EXPECT_LT(best, 0.02) << "theta_mu " << theta_mu;
  }
}

TEST(MapSignature, StandardFieldsArePointSymmetricAndAnExtraLineBreaksIt) {
  for (const char* name : {"spl2019", "msl"}) {  // no goal area; the most features
    EXPECT_TRUE(MapSignature(makeStandardField(name)).pointSymmetric()) << name;
  }
  FieldModel field = makeStandardField("spl");
  field.segments.push_back({Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(2.0, 1.0)});
  EXPECT_FALSE(MapSignature(field).pointSymmetric());
}

TEST(MapSignature, RectangularFieldsHaveTwoDominantDirections) {
  for (const std::string& name : standardFieldNames()) {
    MapSignature map(makeStandardField(name));
    ASSERT_EQ(map.dominantDirections().size(), 2u) << name;
    std::vector<double> d = map.dominantDirections();
    std::sort(d.begin(), d.end());
    EXPECT_NEAR(d[0], 0.0, 1e-9) << name;
    EXPECT_NEAR(d[1], M_PI / 2, 1e-9) << name;
    ASSERT_EQ(map.circles().size(), 1u) << name;
  }
}

}  // namespace
}  // namespace houghloc
