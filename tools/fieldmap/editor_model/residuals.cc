#include "tools/fieldmap/editor_model/residuals.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "field_models/field_distance.h"

namespace houghloc::fieldmap {
namespace {

ResidualStats statsOf(std::vector<double> distances) {
  ResidualStats s;
  s.count = static_cast<int>(distances.size());
  if (distances.empty()) return s;
  std::sort(distances.begin(), distances.end());
  double sum = 0.0;
  for (double d : distances) sum += d;
  s.mean_m = sum / s.count;
  // Nearest-rank 95th percentile.
  const int rank = static_cast<int>(std::ceil(0.95 * s.count)) - 1;
  s.p95_m = distances[std::clamp(rank, 0, s.count - 1)];
  return s;
}

}  // namespace

ResidualReport computeResiduals(const FieldModel& field,
                                const std::vector<Eigen::Vector2d>& points_robot,
                                const Pose2& field_T_robot, const ResidualConfig& config) {
  ResidualReport report;
  std::vector<double> all;
  std::map<std::pair<int, int>, std::vector<double>> per_feature;  // (kind, index) -> distances
  for (const Eigen::Vector2d& p : points_robot) {
    const NearestFeature nearest = nearestFeature(field, field_T_robot.transform(p));
    if (nearest.feature.index < 0 || !(nearest.distance_m <= config.max_distance_m)) {
      ++report.unmatched;
      continue;
    }
    all.push_back(nearest.distance_m);
    per_feature[{static_cast<int>(nearest.feature.kind), nearest.feature.index}].push_back(
        nearest.distance_m);
  }
  report.overall = statsOf(std::move(all));
  for (auto& [key, distances] : per_feature) {
    report.features.push_back({FeatureRef{static_cast<FeatureKind>(key.first), key.second},
                               statsOf(std::move(distances))});
  }
  return report;
}

}  // namespace houghloc::fieldmap
