#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <opencv2/core.hpp>
#include <vector>

namespace houghloc {

/// A tileable noise texture (zero mean, unit standard deviation at full resolution) with a mip
/// chain, sampled at a ground position with the pixel's footprint so far-away texture averages
/// out instead of aliasing into noise.
class NoiseTexture {
 public:
  NoiseTexture() = default;
  /// size_px: a power of two; texel_m: texel size at full resolution; blur_texels: Gaussian
  /// correlation length of the noise.
  NoiseTexture(int size_px, double texel_m, double blur_texels, std::uint64_t seed);

  /// Bilinear sample at (x_m, y_m) from the mip level whose texel matches footprint_m. Inline:
  /// the turf calls it several times per pixel.
  float sample(float x_m, float y_m, float footprint_m) const {
    const float ratio = footprint_m * inv_texel_;
    int level = 0;
    if (ratio >= 2.0f) {
      std::uint32_t bits;  // floor(log2(ratio)) from the float's exponent
      std::memcpy(&bits, &ratio, sizeof(bits));
      level = static_cast<int>((bits >> 23) & 0xffu) - 127;
    }
    if (level >= static_cast<int>(levels_.size())) return 0.0f;
    const cv::Mat1f& tex = levels_[level];
    const float scale = inv_texel_ / static_cast<float>(1 << level);
    const float u = x_m * scale - 0.5f, v = y_m * scale - 0.5f;
    const float fu = std::floor(u), fv = std::floor(v);
    const float au = u - fu, av = v - fv;
    const int mask = tex.cols - 1;  // power-of-two size: wrap with a mask
    const int c0 = static_cast<int>(fu) & mask, r0 = static_cast<int>(fv) & mask;
    const int c1 = (c0 + 1) & mask, r1 = (r0 + 1) & mask;
    const float* row0 = tex.ptr<float>(r0);
    const float* row1 = tex.ptr<float>(r1);
    return (1.0f - av) * ((1.0f - au) * row0[c0] + au * row0[c1]) +
           av * ((1.0f - au) * row1[c0] + au * row1[c1]);
  }
  bool empty() const { return levels_.empty(); }

 private:
  std::vector<cv::Mat1f> levels_;
  float inv_texel_ = 1.0f;
};

}  // namespace houghloc
