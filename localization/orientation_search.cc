#include "localization/orientation_search.h"

#include <algorithm>
#include <cmath>

#include "field_models/pose2.h"

namespace houghloc {

std::vector<double> circularCorrelation(const std::vector<double>& h,
                                        const std::vector<double>& m) {
  const int n = static_cast<int>(std::min(h.size(), m.size()));
  // c[k] = sum_i h[i] m[(i + k) mod n], summed over i in order. Term i of every shift at once,
  // over m written out twice (no wrap inside the loop), which the compiler vectorises.
  std::vector<double> twice(m.begin(), m.begin() + n);
  twice.insert(twice.end(), m.begin(), m.begin() + n);
  std::vector<double> c(n, 0.0);
  double* out = c.data();
  for (int i = 0; i < n; ++i) {
    const double hi = h[i];
    const double* shifted = twice.data() + i;
    for (int k = 0; k < n; ++k) out[k] += hi * shifted[k];
  }
  return c;
}

std::vector<OrientationCandidate> findOrientationCandidates(const std::vector<double>& h,
                                                            const std::vector<double>& m,
                                                            const OrientationConfig& config) {
  std::vector<OrientationCandidate> out;
  const std::vector<double> c = circularCorrelation(h, m);
  const int n = static_cast<int>(c.size());
  if (n < 3) return out;
  const double step = M_PI / n;
  const double best = *std::max_element(c.begin(), c.end());
  if (!(best >= config.min_correlation)) return out;
  std::vector<int> maxima;
  for (int k = 0; k < n; ++k) {
    const double prev = c[(k + n - 1) % n], next = c[(k + 1) % n];
    if (c[k] > prev && c[k] >= next && c[k] >= config.min_correlation &&
        c[k] >= config.relative_share * best) {
      maxima.push_back(k);
    }
  }
  std::sort(maxima.begin(), maxima.end(), [&](int a, int b) { return c[a] > c[b]; });
  std::vector<double> kept;
  for (int k : maxima) {
    if (static_cast<int>(kept.size()) >= config.max_candidates) break;
    // Sub-column peak position from a parabola through the three columns around the maximum.
    const double prev = c[(k + n - 1) % n], next = c[(k + 1) % n];
    const double denom = prev - 2.0 * c[k] + next;
    const double offset = denom < 0.0 ? std::clamp(0.5 * (prev - next) / denom, -0.5, 0.5) : 0.0;
    const double phi = (k + offset) * step;
    bool close = false;
    for (double other : kept) {
      // Period pi: phi and phi + pi are the same column.
      const double d = std::abs(normalizeAngle(2.0 * (phi - other))) / 2.0;
      close |= d < config.suppression_rad;
    }
    if (close) continue;
    kept.push_back(phi);
    out.push_back({normalizeAngle(phi), c[k]});
    out.push_back({normalizeAngle(phi + M_PI), c[k]});
  }
  return out;
}

}  // namespace houghloc
