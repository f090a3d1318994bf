#include "tests/localization/localizer_test_support.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "field_models/field_distance.h"

namespace houghloc::testing {

bool correctPose(const Pose2& estimate, const Pose2& truth) {
  return (estimate.translation() - truth.translation()).norm() <= 0.10 &&
         std::abs(angleDifference(estimate.theta, truth.theta)) <= 3.0 * M_PI / 180.0;
}

bool correctUpToSymmetry(const Pose2& estimate, const Pose2& truth) {
  return correctPose(estimate, truth) || correctPose(estimate, mirrored(truth));
}

bool estimateCorrect(const LocalizationEstimate& estimate, const Pose2& truth) {
  const auto best = estimate.best();
  return best && correctUpToSymmetry(best->mean, truth);
}

bool seesTwoDirections(const FieldModel& field, const Pose2& field_T_robot,
                       const GroundPoints& points, int min_points) {
  int along_x = 0, along_y = 0;
  for (const GroundPoint& p : points.points) {
    const NearestFeature nearest = nearestFeature(field, field_T_robot.transform(p.p_robot));
    if (nearest.distance_m > 0.05 || nearest.feature.index < 0) continue;
    if (nearest.feature.kind == FeatureKind::kSegment) {
      const Eigen::Vector2d d = field.segments[nearest.feature.index].direction();
      (std::abs(d.x()) >= std::abs(d.y()) ? along_x : along_y) += 1;
    } else if (nearest.feature.kind == FeatureKind::kArc) {
      ++along_x;
      ++along_y;
    }
  }
  return along_x >= min_points && along_y >= min_points;
}

bool estimateFinite(const LocalizationEstimate& estimate) {
  double sum = 0.0;
  for (const EstimateHypothesis& h : estimate.hypotheses) {
    if (!h.pose.mean.isFinite() || !h.pose.covariance.allFinite()) return false;
    if (!(h.pose.weight >= 0.0 && h.pose.weight <= 1.0)) return false;
    sum += h.pose.weight;
  }
  if (!estimate.hypotheses.empty() && std::abs(sum - 1.0) > 1e-9) return false;
  return std::isfinite(estimate.global_ms) && std::isfinite(estimate.tracker_ms);
}

bool sameEstimate(const LocalizationEstimate& a, const LocalizationEstimate& b) {
  if (a.t_us != b.t_us || a.status != b.status || a.points_in != b.points_in ||
      a.points_used != b.points_used || a.global_ran != b.global_ran || a.fallen != b.fallen ||
      a.hypotheses.size() != b.hypotheses.size()) {
    return false;
  }
  for (size_t k = 0; k < a.hypotheses.size(); ++k) {
    const EstimateHypothesis& x = a.hypotheses[k];
    const EstimateHypothesis& y = b.hypotheses[k];
    if (x.id != y.id || x.age_frames != y.age_frames || x.pose.weight != y.pose.weight ||
        x.pose.mean.x != y.pose.mean.x || x.pose.mean.y != y.pose.mean.y ||
        x.pose.mean.theta != y.pose.mean.theta || x.pose.covariance != y.pose.covariance) {
      return false;
    }
  }
  return true;
}

ScenarioConfig walkOn(const FieldModel& field, int frames, std::uint32_t seed) {
  ScenarioConfig config;
  config.frames = frames;
  config.seed = seed;
  config.half_extent_x_m = 0.33 * field.field_length;
  config.half_extent_y_m = 0.3 * field.field_width;
  config.max_range_m *= std::max(1.0, field.field_length / 9.0);
  return config;
}

Pose3 uprightCamera() {
  Pose3 camera;
  camera.x = 0.05;
  camera.z = 0.5;
  camera.pitch = 0.2;
  return camera;
}

LocalizationHint hint(HintKind kind, std::vector<GaussianPose> poses) {
  LocalizationHint h;
  h.kind = kind;
  h.poses = std::move(poses);
  return h;
}

GaussianPose gaussianAt(const Pose2& mean, double weight, double sigma_m, double sigma_rad) {
  GaussianPose g;
  g.mean = mean;
  g.covariance =
      Eigen::Vector3d(sigma_m * sigma_m, sigma_m * sigma_m, sigma_rad * sigma_rad).asDiagonal();
  g.weight = weight;
  return g;
}

}  // namespace houghloc::testing
