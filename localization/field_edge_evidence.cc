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
  const double ox = field_T_robot.x, oy = field_T_robot.y;
  // Off the carpet every predicted range is 0 (rangeToRectangle): all samples are seen farther.
  const bool off = !(std::abs(ox) <= half_length && std::abs(oy) <= half_width);
  const double c = std::cos(field_T_robot.theta), s = std::sin(field_T_robot.theta);
  double sum = 0.0;
  for (const Sample& sample : samples_) {
    // rangeToRectangle written out, with its inside test hoisted out of the loop: calling it per
    // sample made MSL's locate() 3-6 % slower (same results). The ray leaves through the nearer
    // of the walls it runs towards.
    const double dx = c * sample.direction.x() - s * sample.direction.y();
    const double dy = s * sample.direction.x() + c * sample.direction.y();
    const double to_x = (std::copysign(half_length, dx) - ox) / dx;  // +inf when dx == 0
    const double to_y = (std::copysign(half_width, dy) - oy) / dy;
    const double predicted = off ? 0.0 : std::min(to_x, to_y);
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
