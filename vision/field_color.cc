#include "vision/field_color.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "vision/pixel_access.h"

namespace houghloc {
namespace {

struct Sample {
  float r, g;
  int luma;
  bool bottom;     ///< in the bottom band of the image
  int diff_below;  ///< |luma change| to the sample one step below (-1: none)
  int row;         ///< image row (v)
};

float median(std::vector<float> values) {
  if (values.empty()) return 0.f;
  auto mid = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

/// The q-quantile (0-1) of values, reordering them; 0 when empty.
float quantile(std::vector<float>* values, double q) {
  if (values->empty()) return 0.f;
  auto it = values->begin() + static_cast<long>(q * (values->size() - 1));
  std::nth_element(values->begin(), it, values->end());
  return *it;
}

float greyDistance(cv::Point2f c) { return std::hypot(c.x - 1.f / 3.f, c.y - 1.f / 3.f); }

/// Squared chromaticity distance of a sample from `centre`: compared with squared radii, so the
/// loops over all samples need no square root.
float squaredDistance(const Sample& s, cv::Point2f centre) {
  const float dr = s.r - centre.x, dg = s.g - centre.y;
  return dr * dr + dg * dg;
}

template <typename Pixels>
std::vector<Sample> collectSamples(const Pixels& pixels, const std::vector<int>& start_rows,
                                   const FieldColorConfig& config) {
  std::vector<Sample> samples;
  const int step = std::max(1, config.sample_step_px);
  const int rows = pixels.rows();
  const int bottom_row = rows - static_cast<int>(config.bottom_band_share * rows);
  for (int u = step / 2; u < pixels.cols(); u += step) {
    const int top = std::max(0, start_rows[static_cast<size_t>(u)]);
    int below = -1;  // luma of the sample one step below in this column, -1: none
    for (int v = rows - 1 - step / 2; v >= top; v -= step) {
      const BgrBytes p = pixels.at(u, v);
      const int luma = FieldColor::luma(p.data());
      if (luma < config.min_luma) {
        below = -1;
        continue;
      }
      const float sum = static_cast<float>(p[0] + p[1] + p[2]);
      samples.push_back({p[2] / sum, p[1] / sum, luma, v >= bottom_row,
                         below >= 0 ? std::abs(luma - below) : -1, v});
      below = luma;
    }
  }
  return samples;
}

/// Local maxima of the 3x3-smoothed chromaticity histogram, largest first.
std::vector<cv::Point2f> histogramPeaks(const std::vector<Sample>& samples, int bins) {
  std::vector<int> hist(static_cast<size_t>(bins * bins), 0), smooth(hist.size(), 0);
  const auto bin = [bins](float x) { return std::clamp(static_cast<int>(x * bins), 0, bins - 1); };
  for (const Sample& s : samples) ++hist[static_cast<size_t>(bin(s.g) * bins + bin(s.r))];
  const auto at = [bins](std::vector<int>& h, int gi, int ri) -> int& {
    return h[static_cast<size_t>(gi * bins + ri)];
  };
  for (int gi = 1; gi + 1 < bins; ++gi) {
    for (int ri = 1; ri + 1 < bins; ++ri) {
      for (int dg = -1; dg <= 1; ++dg) {
        for (int dr = -1; dr <= 1; ++dr) at(smooth, gi, ri) += at(hist, gi + dg, ri + dr);
      }
    }
  }
  std::vector<std::pair<int, cv::Point2f>> peaks;
  for (int gi = 1; gi + 1 < bins; ++gi) {
    for (int ri = 1; ri + 1 < bins; ++ri) {
      const int value = at(smooth, gi, ri);
      bool is_max = value > 0;
      for (int dg = -1; dg <= 1 && is_max; ++dg) {
        for (int dr = -1; dr <= 1 && is_max; ++dr) {
          const int other = at(smooth, gi + dg, ri + dr);
          // Ties go to the first bin in scan order, so a plateau gives one peak.
          if (other > value || (other == value && (dg < 0 || (dg == 0 && dr < 0)))) {
            is_max = (dg == 0 && dr == 0);
          }
        }
      }
      if (is_max) peaks.push_back({value, {(ri + 0.5f) / bins, (gi + 0.5f) / bins}});
    }
  }
  std::sort(peaks.begin(), peaks.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<cv::Point2f> out;
  for (const auto& peak : peaks) out.push_back(peak.second);
  return out;
}

/// How much the image says a chromaticity cluster is the turf: its share of the samples, how
/// much of the image's bottom band it fills (a standing robot sees the field below it; walls,
/// floors and people beyond the border do not reach the bottom) and how clearly it is coloured
/// rather than grey (walls, floors and ceilings are near grey; turf is green to teal).
double turfEvidence(const std::vector<Sample>& samples, cv::Point2f centre,
                    const FieldColorConfig& config) {
  const float grey = greyDistance(centre);
  // Turf is green to teal: green above red. Yellow, red and brown (wood, skin) are not turf.
  if (grey < config.min_grey_distance || centre.y < centre.x + config.min_green_over_red) return 0;
  int near = 0, near_bottom = 0, bottom = 0;
  const float radius = static_cast<float>(config.max_chroma_radius);
  for (const Sample& s : samples) {
    const bool in = squaredDistance(s, centre) < radius * radius;
    near += in;
    bottom += s.bottom;
    near_bottom += in && s.bottom;
  }
  const double share = static_cast<double>(near) / samples.size();
  const double bottom_share = bottom > 0 ? static_cast<double>(near_bottom) / bottom : 0.0;
  const double colourful = std::min(1.0, grey / config.clear_grey_distance);
  return share * (config.bottom_weight_floor + bottom_share) * colourful;
}

/// The cluster with the most turf evidence among `peaks` (the largest histogram peaks) and the
/// previous frame's field colour (when given). Falls back to the largest peak (then judged
/// invalid).
cv::Point2f turfPeak(const std::vector<Sample>& samples, const std::vector<cv::Point2f>& peaks,
                     const FieldColorConfig& config, const FieldColor* previous) {
  if (peaks.empty()) return {1.f / 3.f, 1.f / 3.f};
  cv::Point2f best = peaks.front();
  double best_score = 0.0;
  for (const cv::Point2f& peak : peaks) {
    const double score = turfEvidence(samples, peak, config);
    if (score > best_score) best_score = score, best = peak;
  }
  if (previous && previous->valid) {
    // The previous estimate wins only where this frame still holds it (no wrong estimate sticks).
    // Its bonus steadies the estimate within one turf, whose peak moves a little from frame to
    // frame; a cluster further than max_chroma_radius from this frame's best must win on its
    // evidence alone (a view that turned from shaded to sunlit turf takes the sunlit one).
    const cv::Point2f kept(previous->r, previous->g);
    const cv::Point2f moved = kept - best;
    const float radius = static_cast<float>(config.max_chroma_radius);
    const double bonus = moved.dot(moved) <= radius * radius ? config.memory_bonus : 1.0;
    const double score = bonus * turfEvidence(samples, kept, config);
    if (score > best_score) best = kept;
  }
  return best;
}

/// Lumas (0-255) of a set of samples as a histogram: medians and robust spreads of any luma
/// range without sorting (a frame has thousands of field samples).
class LumaHistogram {
 public:
  explicit LumaHistogram(const std::vector<float>& lumas) {
    for (float l : lumas) ++count_[static_cast<std::size_t>(std::clamp(l, 0.f, 255.f))];
  }
  int count(int from, int to) const {  // samples with luma in [from, to)
    int n = 0;
    for (int l = from; l < to; ++l) n += count_[static_cast<std::size_t>(l)];
    return n;
  }
  /// The luma of rank count(from, to) / 2 in [from, to) (median() of those samples), 0 if none.
  int median(int from, int to) const {
    const int n = count(from, to);
    return n > 0 ? atRank(count_, from, to, n / 2) : 0;
  }
  /// 1.4826 x the median absolute deviation of the samples with luma in [from, to): the sigma of
  /// a Gaussian, robust to outliers.
  float robustSigma(int from, int to) const {
    const int n = count(from, to);
    if (n == 0) return 0.f;
    const int centre = median(from, to);
    std::array<int, 256> deviations{};
    for (int l = from; l < to; ++l) {
      deviations[static_cast<std::size_t>(std::abs(l - centre))] +=
          count_[static_cast<std::size_t>(l)];
    }
    return 1.4826f * static_cast<float>(atRank(deviations, 0, 256, n / 2));
  }
  /// Otsu's split: the luma that starts the upper of two classes with the largest between-class
  /// variance (0: no split).
  int otsuSplit() const {
    const double n = count(0, 256);
    double total = 0.0;
    for (int l = 0; l < 256; ++l)
      total += static_cast<double>(l) * count_[static_cast<std::size_t>(l)];
    double below = 0.0, sum_below = 0.0, best_between = -1.0;
    int split = 0;
    for (int l = 1; l < 256; ++l) {
      below += count_[static_cast<std::size_t>(l - 1)];
      sum_below += (l - 1.0) * count_[static_cast<std::size_t>(l - 1)];
      if (below == 0.0 || below == n || count_[static_cast<std::size_t>(l)] == 0) continue;
      const double gap = (total - sum_below) / (n - below) - sum_below / below;
      const double between = below * (n - below) * gap * gap;
      if (between > best_between) best_between = between, split = l;
    }
    return split;
  }

 private:
  static int atRank(const std::array<int, 256>& counts, int from, int to, int rank) {
    for (int l = from; l < to; ++l) {
      rank -= counts[static_cast<std::size_t>(l)];
      if (rank < 0) return l;
    }
    return to - 1;
  }
  std::array<int, 256> count_{};
};

/// Splits the field samples into shade and lit turf (FieldColor::lit_split) where they form two
/// light levels: Otsu's split of their lumas (the largest between-level variance), kept when
/// both levels are large and their medians far enough apart to be light rather than texture.
void splitLightLevels(const LumaHistogram& histogram, const FieldColorConfig& config,
                      FieldColor* color) {
  color->lit_split = 256.f;
  const int split = histogram.otsuSplit();
  const double min_count = config.min_light_share * histogram.count(0, 256);
  if (split == 0 || histogram.count(0, split) < min_count ||
      histogram.count(split, 256) < min_count) {
    return;
  }
  if (histogram.median(split, 256) < config.min_light_ratio * histogram.median(0, split)) return;
  color->lit_split = static_cast<float>(split);
  color->shade_sigma = histogram.robustSigma(0, split);
  color->lit_sigma = histogram.robustSigma(split, 256);
}

/// The turf's texture from the |luma changes| between neighbouring samples: the spread of their
/// differences / sqrt 2 (the median |difference| of two Gaussian samples is 0.954 sigma).
/// Reorders `diffs`.
float textureSigma(std::vector<float>* diffs) { return quantile(diffs, 0.5) / 0.954f; }

/// FieldColor::band_texture_sigma: texture_sigma's measure (the luma change to the sample
/// below) of the field samples per band of image rows.
void textureByBand(const std::vector<const Sample*>& field_samples, int image_rows,
                   const FieldColorConfig& config, FieldColor* color) {
  const int bands = std::clamp(config.texture_bands, 1, FieldColor::kMaxTextureBands);
  color->texture_band_rows = (image_rows + bands - 1) / bands;
  std::array<std::vector<float>, FieldColor::kMaxTextureBands> diffs;
  for (const Sample* s : field_samples) {
    const int band = std::min(bands - 1, s->row / color->texture_band_rows);
    diffs[static_cast<size_t>(band)].push_back(static_cast<float>(s->diff_below));
  }
  for (size_t b = 0; b < diffs.size(); ++b) {
    color->band_texture_sigma[b] = static_cast<int>(diffs[b].size()) >= config.min_band_samples
                                       ? textureSigma(&diffs[b])
                                       : color->texture_sigma;
  }
}

/// A chromaticity disc refined from a peak: the mean of the samples within max_chroma_radius
/// (twice, as the centre moves), and a robust spread around it; `accept` picks the samples that
/// may count. Radius 0 when none lie near.
struct Disc {
  cv::Point2f centre;
  float radius = 0.f;
};
template <typename Accept>
Disc refineDisc(const std::vector<Sample>& samples, cv::Point2f centre,
                const FieldColorConfig& config, Accept&& accept) {
  float radius = static_cast<float>(config.max_chroma_radius);
  for (int iteration = 0; iteration < 2; ++iteration) {
    double sum_r = 0.0, sum_g = 0.0;
    std::vector<float> distances;
    for (const Sample& s : samples) {
      const float d2 = squaredDistance(s, centre);
      if (d2 < radius * radius && accept(s)) {
        sum_r += s.r, sum_g += s.g, distances.push_back(std::sqrt(d2));
      }
    }
    if (distances.empty()) return {centre, 0.f};
    centre = {static_cast<float>(sum_r / distances.size()),
              static_cast<float>(sum_g / distances.size())};
    // The median distance of a 2-D Gaussian is 1.177 sigma.
    const float sigma = median(distances) / 1.177f;
    // A desaturated turf (dim or tinted light) keeps grey (white paint) outside its radius.
    const float limit = std::min(static_cast<float>(config.max_chroma_radius),
                                 static_cast<float>(config.max_grey_share) * greyDistance(centre));
    radius = std::clamp(static_cast<float>(config.radius_sigmas) * sigma,
                        std::min(static_cast<float>(config.min_chroma_radius), limit), limit);
  }
  return {centre, radius};
}

/// The turf in the shade (FieldColorConfig::max_other_light_distance): among `peaks` (the
/// largest histogram peaks) outside the field's disc, the one with the most samples whose median
/// luma is min_light_ratio times darker than the field's. Radius 0 when none.
Disc otherLight(const std::vector<Sample>& samples, const std::vector<cv::Point2f>& peaks,
                const Disc& field, float field_luma, int field_samples,
                const FieldColorConfig& config) {
  Disc best;
  if (config.max_other_light_distance <= 0.0) return best;
  const auto outside = [&](const Sample& s) {
    return squaredDistance(s, field.centre) >= field.radius * field.radius;
  };
  std::size_t best_count = 0;
  for (const cv::Point2f& peak : peaks) {
    const cv::Point2f moved = peak - field.centre;
    if (moved.dot(moved) > config.max_other_light_distance * config.max_other_light_distance ||
        moved.dot(moved) < field.radius * field.radius) {
      continue;
    }
    const Disc disc = refineDisc(samples, peak, config, outside);
    const float grey = greyDistance(disc.centre);
    if (disc.radius <= 0.f || grey < config.min_grey_distance || grey <= disc.radius ||
        disc.centre.y < disc.centre.x + config.min_green_over_red) {
      continue;
    }
    std::vector<float> lumas;
    for (const Sample& s : samples) {
      if (outside(s) && squaredDistance(s, disc.centre) < disc.radius * disc.radius) {
        lumas.push_back(static_cast<float>(s.luma));
      }
    }
    if (lumas.size() < config.min_light_share * field_samples || lumas.size() <= best_count) {
      continue;
    }
    // Shade only: what is brighter than the turf is more often a window or a sunlit wall.
    if (median(lumas) * config.min_light_ratio > field_luma) continue;
    best = disc;
    best_count = lumas.size();
  }
  return best;
}

}  // namespace

FieldColor estimateFieldColor(const cv::Mat& image, const std::vector<int>& start_rows,
                              const FieldColorConfig& config, const FieldColor* previous) {
  FieldColor color;
  const std::vector<Sample> samples = visitPixels(
      image, [&](const auto& pixels) { return collectSamples(pixels, start_rows, config); });
  if (samples.size() < 10) return color;
  std::vector<cv::Point2f> peaks = histogramPeaks(samples, config.histogram_bins);
  if (static_cast<int>(peaks.size()) > config.max_candidates) {
    peaks.resize(static_cast<size_t>(config.max_candidates));
  }
  cv::Point2f centre = turfPeak(samples, peaks, config, previous);

  // Refine: mean of the samples near the peak, then a robust spread around it.
  const Disc field = refineDisc(samples, centre, config, [](const Sample&) { return true; });
  if (field.radius <= 0.f) return color;
  centre = field.centre;
  const float radius = field.radius;

  std::vector<float> lumas, local_diffs;
  std::vector<const Sample*> textured;  // field samples with a luma change below them
  for (const Sample& s : samples) {
    if (squaredDistance(s, centre) < radius * radius) {
      lumas.push_back(s.luma);
      if (s.diff_below < 0) continue;
      local_diffs.push_back(s.diff_below);
      textured.push_back(&s);
    }
  }
  color.r = centre.x;
  color.g = centre.y;
  color.radius = radius;
  color.chroma_noise = static_cast<float>(config.chroma_noise);
  color.field_share = static_cast<float>(lumas.size()) / samples.size();
  const LumaHistogram histogram(lumas);
  color.luma_median = static_cast<float>(histogram.median(0, 256));
  const Disc other =
      otherLight(samples, peaks, field, color.luma_median, static_cast<int>(lumas.size()), config);
  color.other_r = other.centre.x;
  color.other_g = other.centre.y;
  color.other_radius = other.radius;
  color.luma_sigma = histogram.robustSigma(0, 256);
  splitLightLevels(histogram, config, &color);
  // Neighbouring samples in a column, 12 px apart, differ by the turf's texture and noise but
  // hardly by the light (gradients, vignetting, shadows change over tens of px): their
  // differences measure the texture alone.
  color.texture_sigma = textureSigma(&local_diffs);
  textureByBand(textured, image.rows, config, &color);
  color.min_luma = std::max(static_cast<float>(config.min_luma),
                            static_cast<float>(config.shadow_luma_ratio) * color.luma_median);
  const float grey_distance = greyDistance(centre);
  color.white_radius = static_cast<float>(config.white_chroma_ratio) * grey_distance;
  color.valid = color.field_share >= config.min_field_share &&
                grey_distance >= config.min_grey_distance && grey_distance > radius &&
                centre.y >= centre.x + config.min_green_over_red;
  return color;
}

}  // namespace houghloc
