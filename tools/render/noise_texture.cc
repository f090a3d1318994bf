#include "tools/render/noise_texture.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace houghloc {

NoiseTexture::NoiseTexture(int size_px, double texel_m, double blur_texels, std::uint64_t seed)
    : inv_texel_(static_cast<float>(1.0 / texel_m)) {
  cv::Mat1f noise(size_px, size_px);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, 1.0);
  if (blur_texels > 0.0) {
    // Blur with wrap-around so the texture tiles seamlessly.
    const int pad = static_cast<int>(std::ceil(4.0 * blur_texels)) + 1;
    cv::Mat1f padded, blurred;
    cv::copyMakeBorder(noise, padded, pad, pad, pad, pad, cv::BORDER_WRAP);
    cv::GaussianBlur(padded, blurred, cv::Size(), blur_texels);
    noise = blurred(cv::Rect(pad, pad, size_px, size_px)).clone();
  }
  cv::Scalar mean, stddev;
  cv::meanStdDev(noise, mean, stddev);
  noise = (noise - mean[0]) / std::max(1e-9, stddev[0]);
  levels_.push_back(noise);
  while (levels_.back().rows > 2) {
    cv::Mat1f half;
    cv::resize(levels_.back(), half, cv::Size(), 0.5, 0.5, cv::INTER_AREA);  // 2x2 means
    levels_.push_back(half);
  }
}

float NoiseTexture::sample(float x_m, float y_m, float footprint_m) const {
  const float ratio = footprint_m * inv_texel_;
  int level = ratio > 1.0f ? std::ilogb(ratio) : 0;
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

}  // namespace houghloc
