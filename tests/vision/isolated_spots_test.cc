// The spot support test (vision/isolated_spots.h): which spots have another within the radius,
// against a plain all-pairs count, and which ones dropIsolated drops.
#include "vision/isolated_spots.h"

#include <gtest/gtest.h>

#include <random>

namespace houghloc {
namespace {

LineSpot spotAt(float u, float v, float width_px) {
  LineSpot s;
  s.pixel = Eigen::Vector2f(u, v);
  s.width_px = width_px;
  return s;
}

TEST(IsolatedSpots, NeighboursAsAnAllPairsSearchFindsThem) {
  // Clusters and scattered pixels, also at negative coordinates and on cell borders.
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> coordinate(-200.f, 900.f);
  for (const float radius : {5.f, 32.f, 96.f, 250.f}) {
    std::vector<Eigen::Vector2f> pixels;
    for (int i = 0; i < 300; ++i) pixels.emplace_back(coordinate(rng), coordinate(rng));
    pixels.emplace_back(5000.f, 5000.f);  // alone
    pixels.emplace_back(radius, 0.f);     // exactly the radius apart: counts as near
    pixels.emplace_back(0.f, 0.f);
    const std::vector<char> near = hasNeighbourWithin(pixels, radius);
    ASSERT_EQ(near.size(), pixels.size());
    int with = 0;
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      bool expected = false;
      for (std::size_t j = 0; j < pixels.size(); ++j) {
        expected = expected || (j != i && (pixels[j] - pixels[i]).norm() <= radius);
      }
      EXPECT_EQ(static_cast<bool>(near[i]), expected) << "pixel " << i << ", radius " << radius;
      with += expected;
    }
    EXPECT_TRUE(near[near.size() - 1] && near[near.size() - 2]);
    EXPECT_FALSE(near[near.size() - 3]);
    EXPECT_GT(with, 1);
  }
}

TEST(IsolatedSpots, DropsWideSpotsWithoutSupportAndKeepsTheOrder) {
  SpotSupportConfig config;  // 96 px, 8 px wide
  std::vector<LineSpot> spots = {
      spotAt(100, 100, 20),                        // a line's spots, 32 px apart
      spotAt(132, 100, 20), spotAt(400, 300, 30),  // a wide bar alone: dropped
      spotAt(600, 50, 3),                          // a far line's lone spot: narrow, kept
      spotAt(164, 100, 20),
  };
  EXPECT_EQ(dropIsolated(&spots, config), 1);
  ASSERT_EQ(spots.size(), 4u);
  EXPECT_EQ(spots[0].pixel.x(), 100.f);
  EXPECT_EQ(spots[1].pixel.x(), 132.f);
  EXPECT_EQ(spots[2].pixel.x(), 600.f);
  EXPECT_EQ(spots[3].pixel.x(), 164.f);
  config.enabled = false;
  std::vector<LineSpot> lone = {spotAt(10, 10, 30)};
  EXPECT_EQ(dropIsolated(&lone, config), 0);
  EXPECT_EQ(lone.size(), 1u);
}

}  // namespace
}  // namespace houghloc
