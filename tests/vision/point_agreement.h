// How well two runs' points agree in the image: the share of either run's points that the other
// run has within a pixel distance. Shared by the YUYV tests (tests/vision, tests/real).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <vector>

#include "field_models/ground_points.h"

namespace houghloc::testing {

/// Points of `a` with a point of `b` within max_px (pixel distance).
inline size_t pointsMatched(const std::vector<GroundPoint>& a, const std::vector<GroundPoint>& b,
                            double max_px) {
  size_t matched = 0;
  for (const GroundPoint& p : a) {
    matched += std::any_of(b.begin(), b.end(), [&](const GroundPoint& q) {
      return (p.pixel - q.pixel).cast<double>().norm() <= max_px;
    });
  }
  return matched;
}

/// Matches in both directions of two runs' points (each run's points with a partner in the
/// other run), to be pooled over frames.
struct PointAgreement {
  size_t points_a = 0, points_b = 0;
  size_t matched_a = 0, matched_b = 0;

  void add(const std::vector<GroundPoint>& a, const std::vector<GroundPoint>& b, double max_px) {
    points_a += a.size();
    points_b += b.size();
    matched_a += pointsMatched(a, b, max_px);
    matched_b += pointsMatched(b, a, max_px);
  }
  /// The smaller of the two runs' matched shares (1 when neither run has a point).
  double share() const {
    const auto ratio = [](size_t matched, size_t points) {
      return points == 0 ? 1.0 : static_cast<double>(matched) / points;
    };
    return std::min(ratio(matched_a, points_a), ratio(matched_b, points_b));
  }
};

}  // namespace houghloc::testing
