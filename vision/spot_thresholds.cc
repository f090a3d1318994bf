#include "vision/spot_thresholds.h"

#include <algorithm>
#include <cmath>

#include "vision/line_spots.h"

namespace houghloc {
namespace {

/// Whether the turf at pixel (u, v) is far (LineSpotConfig::far_turf_m_per_px); above the
/// horizon it is not turf.
bool farTurf(const LineWidthModel& widths, const LineSpotConfig& config, float u, float v) {
  if (config.far_turf_m_per_px <= 0.0) return false;
  const float across = widths.metresPerPx(u, v).x();
  return across > 0.f && widths.expectedPx(u, v).x() > 0.f && across >= config.far_turf_m_per_px;
}

}  // namespace

int noiseThreshold(double sigma, double texture, const LineSpotConfig& config) {
  const double noise_sigma = std::min(sigma, config.max_sigma_over_texture * texture);
  return static_cast<int>(std::max(config.min_contrast, config.noise_contrast * noise_sigma));
}

SpotThresholds::SpotThresholds(const FieldColor& color, const LineWidthModel& widths,
                               const LineSpotConfig& config, cv::Size image)
    : lit_split_(static_cast<int>(std::ceil(color.lit_split))),
      min_saturated_luma_(config.headroom_min_peak_luma) {
  const int rows = std::max(1, image.height);
  band_of_row_.assign(static_cast<size_t>(rows), 0);
  // The whole turf's texture, or in far turf (judged at the middle of its band of rows) its
  // band's when that is lower.
  const int band_rows = color.texture_band_rows > 0 ? color.texture_band_rows : rows;
  for (int first = 0, band = 0; first < rows; first += band_rows, ++band) {
    const float middle = std::min(first + 0.5f * band_rows, rows - 0.5f);
    double texture = color.texture_sigma;
    if (color.texture_band_rows > 0 && band < FieldColor::kMaxTextureBands &&
        farTurf(widths, config, 0.5f * image.width, middle)) {
      texture = std::min(texture, static_cast<double>(color.band_texture_sigma[band]));
    }
    const Band thresholds = bandFor(color, config, texture);
    const auto same = [&](const Band& b) {
      return b.shade == thresholds.shade && b.lit == thresholds.lit &&
             b.saturated == thresholds.saturated;
    };
    auto known = std::find_if(bands_.begin(), bands_.end(), same);
    if (known == bands_.end()) known = bands_.insert(bands_.end(), thresholds);
    std::fill(band_of_row_.begin() + first,
              band_of_row_.begin() + std::min(rows, first + band_rows),
              static_cast<uint8_t>(known - bands_.begin()));
  }
}

int SpotThresholds::forPeak(int turf_luma, int v, int peak_luma) const {
  const Band& band = bandOf(v);
  if (peak_luma >= min_saturated_luma_) {
    return band.saturated[static_cast<size_t>(turf_luma)];
  }
  return level(band, turf_luma);
}

const SpotThresholds::Band& SpotThresholds::bandOf(int v) const {
  const int row = std::clamp(v, 0, static_cast<int>(band_of_row_.size()) - 1);
  return bands_[band_of_row_[static_cast<size_t>(row)]];
}

SpotThresholds::Band SpotThresholds::bandFor(const FieldColor& color, const LineSpotConfig& config,
                                             double texture) const {
  const bool two_levels = color.lit_split <= 255.f;
  Band band;
  const int one_level = noiseThreshold(color.luma_sigma, texture, config);
  band.shade = two_levels ? noiseThreshold(color.shade_sigma, texture, config) : one_level;
  // Light scales the turf's texture with its luma: the lit turf's spread is at least the
  // shade's (a smaller one comes from something else in the lit level, such as a robot's
  // green-tinted white close by).
  band.lit = two_levels ? std::max(band.shade, noiseThreshold(color.lit_sigma, texture, config))
                        : one_level;
  // Turf near saturation reaches 255 by its own texture: the cap stops at the texture's floor.
  const double floor = config.headroom_min_textures * texture;
  for (int luma = 0; luma < 256; ++luma) {
    const int by_level = level(band, luma);
    const double cap =
        config.headroom_share > 0.0
            ? std::max({config.min_contrast, floor, config.headroom_share * (255 - luma)})
            : by_level;
    band.saturated[static_cast<size_t>(luma)] =
        static_cast<int16_t>(std::min(by_level, static_cast<int>(cap)));
  }
  return band;
}

}  // namespace houghloc
