#pragma once

#include <array>
#include <opencv2/core.hpp>
#include <vector>

namespace houghloc {

struct FieldColorConfig {
  int sample_step_px = 12;           ///< grid spacing of the colour samples below the horizon
  int histogram_bins = 48;           ///< per chromaticity axis (r and g in [0, 1])
  int min_luma = 20;                 ///< darker samples have unreliable chromaticity (0-255)
  double min_chroma_radius = 0.03;   ///< field chromaticity radius is at least this
  double max_chroma_radius = 0.09;   ///< ... and at most this
  double radius_sigmas = 3.5;        ///< radius = this many robust sigmas of the field samples
  double min_field_share = 0.1;      ///< below this share of field samples no field is found
  double shadow_luma_ratio = 0.25;   ///< field pixels may be this much darker than the median
  double white_chroma_ratio = 0.55;  ///< "low saturation": chroma distance to grey below this
                                     ///< share of the field colour's distance to grey
  double chroma_noise = 10.0;  ///< sensor noise allowance, channel units (0-255): dark pixels'
                               ///< chromaticity is noisier, so they get more room
  // Which chromaticity cluster is the turf (turfEvidence in field_color.cc): no hue thresholds
  // per venue, but what every field shows.
  int max_candidates = 6;             ///< largest histogram peaks compared
  double bottom_band_share = 0.15;    ///< image rows (share of the height) at the bottom where a
                                      ///< standing robot sees the field
  double bottom_weight_floor = 0.25;  ///< evidence = share x (this + bottom share) x colourfulness
  double clear_grey_distance = 0.1;   ///< chromaticity distance to grey counted as fully coloured
  double min_grey_distance = 0.045;   ///< nearer to grey: no turf (grey walls, floors, carpets)
  double min_green_over_red = 0.02;   ///< turf is green to teal: g at least r + this
  double max_grey_share = 0.75;       ///< radius at most this share of the distance to grey
  double memory_bonus = 1.5;          ///< the previous frame's colour wins when this times its
                                      ///< evidence in the current frame beats the best peak; only
                                      ///< within max_chroma_radius of that peak (the same turf),
                                      ///< elsewhere its evidence alone must beat it
  int memory_frames = 10;  ///< the last valid colour is offered for this many frames after it
  // Sun and shade (FieldColor::lit_split): the field samples' lumas split into two light levels
  // when each level holds at least this share of them ...
  double min_light_share = 0.15;
  double min_light_ratio = 1.7;  ///< ... and the lit level's median luma is this many times the
                                 ///< shade's: more than turf texture or vignetting varies
  /// The same turf in the shade (FieldColor::other_r, other_g, other_radius): a chromaticity
  /// cluster at most this far from the field colour's centre, green to teal like it, whose
  /// samples are min_light_ratio times darker than the field's and number at least
  /// min_light_share of them. Sun and shade differ in colour too where the shade is lit by
  /// another source (the sky, the hall's lamps). A brighter cluster is not taken (windows and
  /// sunlit walls are brighter than the turf too). 0 turns it off.
  double max_other_light_distance = 0.18;
  // Texture per band of image rows (FieldColor::band_texture_sigma): far turf, whose blades blur
  // together, is smoother than the near turf that dominates texture_sigma.
  int texture_bands = 4;      ///< bands of equal height (at most FieldColor::kMaxTextureBands)
  int min_band_samples = 40;  ///< a band with fewer field samples keeps texture_sigma
};

/// The turf colour of one frame as normalised chromaticity (r, g) = (R, G) / (R + G + B), which
/// does not change with brightness: lighting gradients, shadows and exposure only scale R, G, B.
/// Colour temperature moves it, which the per-frame estimate follows.
struct FieldColor {
  bool valid = false;
  float r = 0.f, g = 0.f;  ///< chromaticity centre of the field
  float radius = 0.f;      ///< accepted chromaticity distance from the centre
  /// The turf in the shade, where its chromaticity lies outside the radius
  /// (FieldColorConfig::max_other_light_distance): a second disc; other_radius 0 when none.
  float other_r = 0.f, other_g = 0.f, other_radius = 0.f;
  float luma_median = 0.f;    ///< of the field samples, 0-255
  float luma_sigma = 0.f;     ///< robust spread (turf texture and noise), 0-255
  float texture_sigma = 0.f;  ///< the same from luma changes between field samples 12 px
                              ///< apart (/ sqrt 2): texture without the light, 0-255
  float min_luma = 0.f;       ///< darker pixels are not field (shadow limit)
  /// Hard light (sun through windows, outdoors) leaves the turf in two light levels, whose mix
  /// inflates luma_sigma: turf at or above lit_split (0-255) is lit, below it shaded, each level
  /// with its own robust spread. One level (lit_split 256; the two sigmas unused) when the
  /// samples do not split so (FieldColorConfig::min_light_share, min_light_ratio).
  float lit_split = 256.f;
  float shade_sigma = 0.f;  ///< luma spread of the shaded turf, 0-255
  float lit_sigma = 0.f;    ///< ... and of the lit turf
  /// texture_sigma of the field samples in each band of texture_band_rows image rows (band k
  /// from row k x texture_band_rows on), or texture_sigma where a band holds too few of them.
  /// texture_band_rows 0: no bands (a hand-made colour; texture_sigma everywhere).
  static constexpr int kMaxTextureBands = 8;
  int texture_band_rows = 0;
  std::array<float, kMaxTextureBands> band_texture_sigma{};
  float white_radius = 0.f;  ///< chromaticity distance to grey below which a pixel is "white"
  float field_share = 0.f;   ///< share of samples below the horizon that are field
  float chroma_noise = 0.f;  ///< FieldColorConfig::chroma_noise

  /// Luma used throughout the scanlines: (B + 2G + R) / 4, 0-255.
  static int luma(const uchar* bgr) { return (bgr[0] + 2 * bgr[1] + bgr[2]) >> 2; }

  bool isField(const uchar* bgr) const {
    const float sum = static_cast<float>(bgr[0] + bgr[1] + bgr[2]);
    if (luma(bgr) < min_luma) return false;
    return inDisc(bgr, sum, r, g, radius) ||
           (other_radius > 0.f && inDisc(bgr, sum, other_r, other_g, other_radius));
  }
  bool isWhitish(const uchar* bgr) const { return isNearGrey(bgr, white_radius); }
  /// Whether `bgr` is brighter than the mean of `a` and `b` (the pixels beside it) in every
  /// channel, by amounts whose chromaticity lies within white_radius of grey: white light added.
  bool addsWhite(const uchar* bgr, const uchar* a, const uchar* b) const {
    float d[3];
    for (int c = 0; c < 3; ++c) {
      d[c] = bgr[c] - 0.5f * (a[c] + b[c]);
      if (d[c] <= 0.f) return false;
    }
    return isNearGrey(d, white_radius);
  }
  /// Whether the pixel's chromaticity lies within disc_radius of (disc_r, disc_g), with the
  /// noise allowance; sum = B + G + R.
  bool inDisc(const uchar* bgr, float sum, float disc_r, float disc_g, float disc_radius) const {
    const float dr = bgr[2] - disc_r * sum, dg = bgr[1] - disc_g * sum;
    const float tolerance = disc_radius * sum + chroma_noise;
    return dr * dr + dg * dg < tolerance * tolerance;
  }
  /// Whether the pixel's (or a colour difference's: `Channel` float) chromaticity lies within
  /// `radius` of grey (1/3, 1/3).
  template <typename Channel>
  static bool isNearGrey(const Channel* bgr, float radius) {
    const float sum = static_cast<float>(bgr[0] + bgr[1] + bgr[2]);
    const float dr = bgr[2] - sum / 3.f, dg = bgr[1] - sum / 3.f;
    return dr * dr + dg * dg < radius * radius * sum * sum;
  }
};

/// Estimates the field colour from a sparse grid of samples below the given start rows (one per
/// column, e.g. the horizon): among the largest chromaticity clusters the one with the most
/// turf evidence (share, filling the image bottom, coloured rather than grey), so no colour
/// thresholds need tuning on a new field or under new light and a wall, floor or robot larger
/// than the visible turf does not win. previous: the same camera's last valid estimate, kept
/// when this frame still supports it (one odd frame does not lose the field).
/// image: BGR8 or YUYV (pixel_access.h); YUYV pixels are decoded where sampled.
FieldColor estimateFieldColor(const cv::Mat& image, const std::vector<int>& start_rows,
                              const FieldColorConfig& config = {},
                              const FieldColor* previous = nullptr);

}  // namespace houghloc
