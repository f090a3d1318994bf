#include "tools/render/sensor_effects.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace houghloc {
namespace {

/// Line kernel of the image motion during the exposure (uniform along the path).
cv::Mat1f motionKernel(const Eigen::Vector2d& motion) {
  const double length = motion.norm();
  const int half = static_cast<int>(std::ceil(0.5 * length)) + 1;
  cv::Mat1f k = cv::Mat1f::zeros(2 * half + 1, 2 * half + 1);
  const int steps = std::max(4, static_cast<int>(8.0 * length));
  for (int i = 0; i < steps; ++i) {
    const Eigen::Vector2d p = motion * ((i + 0.5) / steps - 0.5) + Eigen::Vector2d(half, half);
    const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
    const float ax = static_cast<float>(p.x() - x), ay = static_cast<float>(p.y() - y);
    k(y, x) += (1 - ax) * (1 - ay);
    k(y, x + 1) += ax * (1 - ay);
    k(y + 1, x) += (1 - ax) * ay;
    k(y + 1, x + 1) += ax * ay;
  }
  return k / cv::sum(k)[0];
}

/// Channel gains of light of a colour temperature the white balance was not set for
/// (warmer light: more red, less blue) and of a green-magenta tint (SensorConfig::tint).
cv::Vec3f whiteBalance(double kelvin, double tint) {
  const double k = std::log(kelvin / 5500.0);
  return cv::Vec3f(static_cast<float>(std::exp(0.45 * k)),
                   static_cast<float>(std::exp(0.25 * tint)),
                   static_cast<float>(std::exp(-0.35 * k)));
}

}  // namespace

ExposureState exposureAt(const SensorConfig& sensor, double t) {
  ExposureState state{sensor.exposure, sensor.color_temperature_k};
  for (const LightChange& c : sensor.light_changes) {
    if (t < c.t_s) break;
    const double f = c.ramp_s > 0.0 ? std::min(1.0, (t - c.t_s) / c.ramp_s) : 1.0;
    state.gain += f * (c.exposure - state.gain);
    state.color_temperature_k += f * (c.color_temperature_k - state.color_temperature_k);
  }
  return state;
}

SensorModel::SensorModel(const SensorConfig& config, int width, int height)
    : config_(config), width_(width), height_(height), vignette_(height, width) {
  const double cx = 0.5 * (width - 1), cy = 0.5 * (height - 1);
  const double r2max = cx * cx + cy * cy;
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      const double r2 = ((c - cx) * (c - cx) + (r - cy) * (r - cy)) / r2max;
      vignette_(r, c) = static_cast<float>(1.0 - config.vignetting * r2);
    }
  }
  cv::Mat1f pool(1, 1 << 22);
  cv::RNG rng(0x5e75u);
  rng.fill(pool, cv::RNG::NORMAL, 0.0, 1.0);
  noise_pool_.assign(pool.begin(), pool.end());
}

cv::Mat3b SensorModel::apply(const cv::Mat3f& scene, const ExposureState& exposure,
                             const Eigen::Vector2d& motion_px, std::uint64_t noise_seed) {
  cv::Mat3f& img = work_;
  if (scene.cols != width_ || scene.rows != height_) {
    cv::resize(scene, img, cv::Size(width_, height_), 0, 0, cv::INTER_AREA);  // box average
  } else {
    scene.copyTo(img);
  }
  // motion_px is zero without motion blur (sensor.motion_blur off and no motion_blur fault).
  if (motion_px.norm() > 0.5) {
    cv::filter2D(img, img, -1, motionKernel(motion_px), cv::Point(-1, -1), 0.0, cv::BORDER_REFLECT);
  }
  if (config_.optics_blur_px > 0.0) {
    cv::GaussianBlur(img, img, cv::Size(), config_.optics_blur_px, 0.0, cv::BORDER_REFLECT);
  }
  cv::RNG rng(noise_seed);
  const size_t pool_mask = noise_pool_.size() - 1;  // a power of two
  size_t next = rng.next() & pool_mask;
  const cv::Vec3f wb = whiteBalance(exposure.color_temperature_k, config_.tint);
  const float gain = static_cast<float>(exposure.gain);
  const float sigma0 = static_cast<float>(config_.noise_sigma);
  const float shot = static_cast<float>(config_.shot_noise);
  out_.create(height_, width_);
  cv::Mat3b& out = out_;
  for (int r = 0; r < height_; ++r) {
    cv::Vec3f* p = img.ptr<cv::Vec3f>(r);
    const float* v = vignette_.ptr<float>(r);
    for (int c = 0; c < width_; ++c) {
      for (int k = 0; k < 3; ++k) {
        const float value = std::max(0.0f, p[c][k] * gain * wb[k] * v[c]);
        const float sigma = sigma0 + shot * std::sqrt(std::min(value, 255.0f) / 255.0f);
        p[c][k] = value + sigma * noise_pool_[next];
        next = (next + 1) & pool_mask;
      }
    }
    if (config_.yuv422) {
      // Average the chroma of pixel pairs (BT.601), keep each pixel's luma.
      for (int c = 0; c + 1 < width_; c += 2) {
        auto luma = [](const cv::Vec3f& b) {
          return 0.114f * b[0] + 0.587f * b[1] + 0.299f * b[2];
        };
        const float y0 = luma(p[c]), y1 = luma(p[c + 1]);
        const float cb = 0.5f * ((p[c][0] - y0) + (p[c + 1][0] - y1));
        const float cr = 0.5f * ((p[c][2] - y0) + (p[c + 1][2] - y1));
        for (int j = 0; j < 2; ++j) {
          const float y = j == 0 ? y0 : y1;
          const float b = y + cb, rr = y + cr;
          const float g = (y - 0.114f * b - 0.299f * rr) / 0.587f;
          p[c + j] = cv::Vec3f(b, g, rr);
        }
      }
    }
    cv::Vec3b* o = out.ptr<cv::Vec3b>(r);
    for (int c = 0; c < width_; ++c) {
      for (int k = 0; k < 3; ++k) o[c][k] = cv::saturate_cast<uchar>(p[c][k]);
    }
  }
  return out.clone();
}

}  // namespace houghloc
