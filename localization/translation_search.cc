#include "localization/translation_search.h"

#include <algorithm>
#include <cmath>

namespace houghloc {

std::vector<double> columnCorrelation(const std::vector<float>& sensor_column,
                                      const std::vector<float>& map_mask, int max_shift_rows) {
  const int sensor_centre = (static_cast<int>(sensor_column.size()) - 1) / 2;
  const int map_centre = (static_cast<int>(map_mask.size()) - 1) / 2;
  std::vector<double> c(2 * max_shift_rows + 1, 0.0);
  // Visit only pairs (map line row, non-empty sensor row): c[k] collects sensor weight that the
  // shift k moves onto a map line.
  std::vector<int> lines;
  for (int j = 0; j < static_cast<int>(map_mask.size()); ++j) {
    if (map_mask[j] > 0.0f) lines.push_back(j - map_centre);
  }
  for (int js = 0; js < static_cast<int>(sensor_column.size()); ++js) {
    const float v = sensor_column[js];
    if (v <= 0.0f) continue;
    const int rho_s = js - sensor_centre;
    for (int rho_m : lines) {
      const int k = rho_m - rho_s;
      if (k >= -max_shift_rows && k <= max_shift_rows) c[k + max_shift_rows] += v;
    }
  }
  return c;
}

std::vector<TranslationConstraint> findTranslationConstraints(const WeightedPoints& sensor,
                                                              const MapSignature& map,
                                                              int direction, double theta_r,
                                                              const TranslationConfig& config) {
  std::vector<TranslationConstraint> out;
  const double step = map.transform().config().rho_step_m;
  const double theta_mu = map.dominantDirections()[direction];
  const FieldModel& field = map.field();
  // The robot stands on the carpet, so |d| is bounded by the carpet's extent along the normal.
  const double max_d = field.outerHalfLength() * std::abs(std::cos(theta_mu)) +
                       field.outerHalfWidth() * std::abs(std::sin(theta_mu));
  const int max_shift = static_cast<int>(std::ceil(max_d / step));
  double sensor_range = step;
  for (const auto& p : sensor.points) sensor_range = std::max(sensor_range, p.norm());
  // Sensor column at theta_mu - theta_R: rho is measured along the rotated normal, no wrap needed.
  const std::vector<float> column = houghColumn(sensor, theta_mu - theta_r, step, sensor_range);
  const std::vector<double> c = columnCorrelation(column, map.lineMask(direction), max_shift);
  const int n = static_cast<int>(c.size());
  if (n < 3) return out;
  const double best = *std::max_element(c.begin(), c.end());
  const double threshold = std::max(config.min_line_weight, config.relative_share * best);
  std::vector<int> maxima;
  for (int k = 0; k < n; ++k) {
    const double prev = k > 0 ? c[k - 1] : 0.0, next = k + 1 < n ? c[k + 1] : 0.0;
    if (c[k] >= threshold && c[k] > prev && c[k] >= next) maxima.push_back(k);
  }
  std::sort(maxima.begin(), maxima.end(), [&](int a, int b) { return c[a] > c[b]; });
  const int window = static_cast<int>(std::round(config.suppression_m / step));
  std::vector<int> kept;
  for (int k : maxima) {
    if (static_cast<int>(kept.size()) >= config.max_peaks) break;
    bool close = false;
    for (int other : kept) close |= std::abs(other - k) <= window;
    if (close) continue;
    kept.push_back(k);
    const double prev = k > 0 ? c[k - 1] : 0.0, next = k + 1 < n ? c[k + 1] : 0.0;
    const double denom = prev - 2.0 * c[k] + next;
    const double offset = denom < 0.0 ? std::clamp(0.5 * (prev - next) / denom, -0.5, 0.5) : 0.0;
    out.push_back({direction, theta_mu, (k - max_shift + offset) * step, c[k]});
  }
  return out;
}

}  // namespace houghloc
