#include "localization/field_edge_evidence.h"

#include <algorithm>
#include <cmath>

namespace houghloc {

FieldEdgeEvidence::FieldEdgeEvidence(const GroundPoints& frame, const FieldEdgeConfig& config)
    : config_(config) {
  if (!config.enabled) return;
  for (const FieldEdgePoint& e : frame.field_edge) {
    const double range = e.p_robot.norm();
    if (!e.p_robot.allFinite() || !std::isfinite(e.range_sigma_m) || e.range_sigma_m < 0.0 ||
        !(range > 1e-3) || range > config.max_range_m) {
      continue;
    }
    const double sigma = std::hypot(e.range_sigma_m, config.sigma_floor_m);
    if (!(sigma > 0.0)) continue;
    samples_.push_back({e.p_robot / range, range, 1.0 / (config.clip_sigmas * sigma)});
  }
  if (static_cast<int>(samples_.size()) < config.min_samples) samples_.clear();
}

double FieldEdgeEvidence::meanCost(const Pose2& field_T_robot, double half_length,
                                   double half_width) const {
  if (samples_.empty()) return 0.0;
  const Eigen::Vector2d origin = field_T_robot.translation();
  const double c = std::cos(field_T_robot.theta), s = std::sin(field_T_robot.theta);
  double sum = 0.0;
  for (const Sample& sample : samples_) {
    const Eigen::Vector2d d(c * sample.direction.x() - s * sample.direction.y(),
                            s * sample.direction.x() + c * sample.direction.y());
    const double predicted = rangeToRectangle(origin, d, half_length, half_width);
    const double e = std::min(1.0, std::abs(sample.range_m - predicted) * sample.inv_sigma);
    sum += (sample.range_m < predicted ? config_.nearer_weight : 1.0) * e * e;
  }
  return sum / static_cast<double>(samples_.size());
}

double FieldEdgeEvidence::penaltyMetres(const Pose2& field_T_robot, double half_length,
                                        double half_width) const {
  return config_.weight_m * meanCost(field_T_robot, half_length, half_width);
}

}  // namespace houghloc
