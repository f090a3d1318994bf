#pragma once

#include <cstdint>
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

  /// Bilinear sample at (x_m, y_m) from the mip level whose texel matches footprint_m.
  float sample(float x_m, float y_m, float footprint_m) const;
  bool empty() const { return levels_.empty(); }

 private:
  std::vector<cv::Mat1f> levels_;
  float inv_texel_ = 1.0f;
};

}  // namespace houghloc
