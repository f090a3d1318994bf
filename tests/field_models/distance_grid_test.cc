#include "field_models/distance_grid.h"

#include <gtest/gtest.h>

#include <random>

#include "field_models/field_distance.h"
#include "field_models/standard_fields.h"

namespace houghloc {
namespace {

struct GridCase {
  std::string field;
  double resolution_m;
};

void PrintTo(const GridCase& c, std::ostream* os) {
  *os << c.field << " at " << c.resolution_m << " m";
}

class DistanceGridTest : public ::testing::TestWithParam<GridCase> {};

// The distance is 1-Lipschitz and a bilinear lookup is a convex combination of the four nodes,
// so the error is at most the largest node distance weighted: half a cell diagonal in the worst
// case (a line end at a cell centre), half a cell for a line through a cell.
TEST_P(DistanceGridTest, BilinearLookupWithinHalfACell) {
  const FieldModel f = makeStandardField(GetParam().field);
  DistanceGridConfig config;
  config.resolution_m = GetParam().resolution_m;
  const DistanceGrid grid(f, config);
  const double r = config.resolution_m;
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> x(-f.outerHalfLength(), f.outerHalfLength());
  std::uniform_real_distribution<double> y(-f.outerHalfWidth(), f.outerHalfWidth());
  double max_error = 0.0, sum_error = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d p(x(rng), y(rng));
    const double error = std::abs(grid.distance(p) - nearestFeature(f, p).distance_m);
    max_error = std::max(max_error, error);
    sum_error += error;
  }
  EXPECT_LE(max_error, 0.5 * std::sqrt(2.0) * r);
  // Away from lines and ridges the distance is linear and the lookup exact, so on average the
  // error is a small fraction of a cell; a grid shifted by half a cell would fail this.
  EXPECT_LT(sum_error / n, 0.05 * r);
}

TEST_P(DistanceGridTest, NodesHoldExactDistances) {
  const FieldModel f = makeStandardField(GetParam().field);
  DistanceGridConfig config;
  config.resolution_m = GetParam().resolution_m;
  const DistanceGrid grid(f, config);
  for (int row = 0; row < grid.rows(); row += 17) {
    for (int col = 0; col < grid.cols(); col += 13) {
      const Eigen::Vector2d p = grid.origin() + grid.resolution() * Eigen::Vector2d(col, row);
      EXPECT_NEAR(grid.distance(p), nearestFeature(f, p).distance_m, 1e-6) << p.transpose();
    }
  }
  // The grid covers the carpet plus the margin.
  EXPECT_LE(grid.origin().x(), -f.outerHalfLength() - config.margin_m + 1e-12);
  EXPECT_GE(grid.origin().x() + (grid.cols() - 1) * grid.resolution(),
            f.outerHalfLength() + config.margin_m - 1e-12);
}

TEST(DistanceGridGradientTest, PointsAwayFromTheNearestLine) {
  const DistanceGrid grid(makeStandardField("spl"));
  Eigen::Vector2d gradient;
  // 0.31 m inside the left touch line (y = 3), far from everything else: d = 3 - y.
  const double d = grid.distance({-1.55, 2.69}, &gradient);
  EXPECT_NEAR(d, 0.31, 1e-6);
  EXPECT_NEAR(gradient.x(), 0.0, 1e-5);
  EXPECT_NEAR(gradient.y(), -1.0, 1e-5);
}

INSTANTIATE_TEST_SUITE_P(FieldsAndResolutions, DistanceGridTest,
                         ::testing::Values(GridCase{"spl", 0.02}, GridCase{"spl2019", 0.05},
                                           GridCase{"kid", 0.03}, GridCase{"adult", 0.05},
                                           GridCase{"msl", 0.1}),
                         [](const auto& info) { return info.param.field; });

}  // namespace
}  // namespace houghloc
