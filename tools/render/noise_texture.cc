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

}  // namespace houghloc
