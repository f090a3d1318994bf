#include "vision/field_color.h"

#include <algorithm>
#include <cmath>

namespace houghloc {
namespace {

struct Sample {
  float r, g;
  int luma;
};

float median(std::vector<float> values) {
  if (values.empty()) return 0.f;
  auto mid = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

std::vector<Sample> collectSamples(const cv::Mat& bgr, const std::vector<int>& start_rows,
                                   const FieldColorConfig& config) {
  std::vector<Sample> samples;
  const int step = std::max(1, config.sample_step_px);
  for (int u = step / 2; u < bgr.cols; u += step) {
    const int top = std::max(0, start_rows[static_cast<size_t>(u)]);
    for (int v = bgr.rows - 1 - step / 2; v >= top; v -= step) {
      const uchar* p = bgr.ptr<uchar>(v) + 3 * u;
      const int luma = FieldColor::luma(p);
      if (luma < config.min_luma) continue;
      const float sum = static_cast<float>(p[0] + p[1] + p[2]);
      samples.push_back({p[2] / sum, p[1] / sum, luma});
    }
  }
  return samples;
}

/// Peak of the 3x3-smoothed chromaticity histogram; green bins (g clearly above r and b) win when
/// they hold a fair share, since a robot close to the camera can outnumber the turf.
cv::Point2f histogramPeak(const std::vector<Sample>& samples, int bins, double min_share) {
  std::vector<int> hist(static_cast<size_t>(bins * bins), 0);
  const auto bin = [bins](float x) { return std::clamp(static_cast<int>(x * bins), 0, bins - 1); };
  for (const Sample& s : samples) ++hist[static_cast<size_t>(bin(s.g) * bins + bin(s.r))];
  int best_any = -1, best_green = -1;
  cv::Point best_any_at, best_green_at;
  for (int gi = 1; gi + 1 < bins; ++gi) {
    for (int ri = 1; ri + 1 < bins; ++ri) {
      int sum = 0;
      for (int dg = -1; dg <= 1; ++dg) {
        for (int dr = -1; dr <= 1; ++dr)
          sum += hist[static_cast<size_t>((gi + dg) * bins + ri + dr)];
      }
      const float r = (ri + 0.5f) / bins, g = (gi + 0.5f) / bins;
      if (sum > best_any) best_any = sum, best_any_at = {ri, gi};
      // Clearly green: a grey wall with a faint green tint must not pass for turf.
      constexpr float kGreenMargin = 0.04f;
      if (g - std::max(r, 1.f - r - g) > kGreenMargin && sum > best_green)
        best_green = sum, best_green_at = {ri, gi};
    }
  }
  const bool green_ok = best_green > 0 && best_green >= min_share * samples.size();
  const cv::Point at = green_ok ? best_green_at : best_any_at;
  return {(at.x + 0.5f) / bins, (at.y + 0.5f) / bins};
}

}  // namespace

FieldColor estimateFieldColor(const cv::Mat& bgr, const std::vector<int>& start_rows,
                              const FieldColorConfig& config) {
  FieldColor color;
  const std::vector<Sample> samples = collectSamples(bgr, start_rows, config);
  if (samples.size() < 10) return color;
  cv::Point2f centre = histogramPeak(samples, config.histogram_bins, config.min_field_share);

  // Refine: mean of the samples near the peak, then a robust spread around it.
  float radius = static_cast<float>(config.max_chroma_radius);
  for (int iteration = 0; iteration < 2; ++iteration) {
    double sum_r = 0.0, sum_g = 0.0;
    std::vector<float> distances;
    for (const Sample& s : samples) {
      const float d = std::hypot(s.r - centre.x, s.g - centre.y);
      if (d < radius) sum_r += s.r, sum_g += s.g, distances.push_back(d);
    }
    if (distances.empty()) return color;
    centre = {static_cast<float>(sum_r / distances.size()),
              static_cast<float>(sum_g / distances.size())};
    // The median distance of a 2-D Gaussian is 1.177 sigma.
    const float sigma = median(distances) / 1.177f;
    radius = std::clamp(static_cast<float>(config.radius_sigmas) * sigma,
                        static_cast<float>(config.min_chroma_radius),
                        static_cast<float>(config.max_chroma_radius));
  }

  std::vector<float> lumas;
  for (const Sample& s : samples) {
    if (std::hypot(s.r - centre.x, s.g - centre.y) < radius) lumas.push_back(s.luma);
  }
  color.r = centre.x;
  color.g = centre.y;
  color.radius = radius;
  color.chroma_noise = static_cast<float>(config.chroma_noise);
  color.field_share = static_cast<float>(lumas.size()) / samples.size();
  color.luma_median = median(lumas);
  std::vector<float> deviations;
  for (float l : lumas) deviations.push_back(std::abs(l - color.luma_median));
  color.luma_sigma = 1.4826f * median(deviations);
  color.min_luma = std::max(static_cast<float>(config.min_luma),
                            static_cast<float>(config.shadow_luma_ratio) * color.luma_median);
  const float grey_distance = std::hypot(centre.x - 1.f / 3.f, centre.y - 1.f / 3.f);
  color.white_radius = static_cast<float>(config.white_chroma_ratio) * grey_distance;
  color.valid = color.field_share >= config.min_field_share && grey_distance > radius;
  return color;
}

}  // namespace houghloc
