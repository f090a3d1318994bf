#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "vision/field_color.h"
#include "vision/line_width_model.h"

namespace houghloc {

struct LineSpotConfig;

/// The contrast a line must have over turf whose luma varies by `sigma` and whose texture
/// (FieldColor::texture_sigma) is `texture`: LineSpotConfig::noise_contrast noise sigmas, the
/// noise sigma being `sigma` but at most max_sigma_over_texture x `texture`.
int noiseThreshold(double sigma, double texture, const LineSpotConfig& config);

/// The contrast a line spot's run must have over the turf it rises from (step 4c; docs/vision.md
/// "Sun and shade", "Far turf", "Saturated light"): noise_contrast x the turf's noise sigma, per
/// light level of the turf (FieldColor::lit_split) and per band of image rows (far turf has its
/// own texture). A line cannot rise above the sensor's 255, so on bright turf a run whose peak
/// saturates is asked at most headroom_share of the rise left there.
class SpotThresholds {
 public:
  /// A threshold for each turf luma (0-255).
  using ByLuma = std::array<int16_t, 256>;

  SpotThresholds(const FieldColor& color, const LineWidthModel& widths,
                 const LineSpotConfig& config, cv::Size image);

  /// Whether every image row has the same thresholds.
  bool uniform() const { return bands_.size() == 1; }

  /// The thresholds of row v for a run whose peak saturates: the scan's test for a candidate
  /// (check() tests the peak).
  const ByLuma& saturatedByLuma(int v) const { return bandOf(v).saturated; }
  int saturated(int turf_luma, int v) const {
    return saturatedByLuma(v)[static_cast<size_t>(turf_luma)];
  }
  /// The threshold for a run rising from turf of this luma in image row v, given its peak's luma.
  int forPeak(int turf_luma, int v, int peak_luma) const;
  /// The shade's threshold in row v (the lower of the two light levels').
  int shade(int v) const { return bandOf(v).shade; }

 private:
  struct Band {
    int shade = 0, lit = 0;  ///< for turf below and at or above lit_split
    ByLuma saturated{};      ///< ... capped by the headroom (not below the texture's floor)
  };
  /// The band's threshold for turf of this luma, by its light level.
  int level(const Band& band, int turf_luma) const {
    return turf_luma >= lit_split_ ? band.lit : band.shade;
  }

  const Band& bandOf(int v) const;
  Band bandFor(const FieldColor& color, const LineSpotConfig& config, double texture) const;

  int lit_split_ = 256;               ///< FieldColor::lit_split, rounded up
  int min_saturated_luma_ = 0;        ///< LineSpotConfig::headroom_min_peak_luma
  std::vector<Band> bands_;           ///< one, or one per band of FieldColor texture rows
  std::vector<uint8_t> band_of_row_;  ///< index into bands_ per image row
};

}  // namespace houghloc
