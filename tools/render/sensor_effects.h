#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "tools/render/scenario.h"

namespace houghloc {

/// Exposure and light colour at one instant (after light changes and their ramps).
struct ExposureState {
  double gain = 1.0;
  double color_temperature_k = 5500.0;
};
ExposureState exposureAt(const SensorConfig& sensor, double t_s);

/// Turns the rendered scene brightness into an 8-bit camera image: downsampling of supersampled
/// renders, motion blur along the image motion during the exposure, lens blur, exposure gain,
/// light colour, vignetting, sensor noise (Gaussian + shot noise), YUV 4:2:2 chroma and
/// quantisation. Deterministic for a seed.
class SensorModel {
 public:
  SensorModel(const SensorConfig& config, int width, int height);

  /// scene: CV_32FC3 at supersampled size; motion_px: image motion of the centre pixel during
  /// the exposure (px at the output size; zero: no motion blur).
  cv::Mat3b apply(const cv::Mat3f& scene, const ExposureState& exposure,
                  const Eigen::Vector2d& motion_px, std::uint64_t noise_seed);

 private:
  SensorConfig config_;
  int width_, height_;
  cv::Mat1f vignette_;
  /// Unit Gaussian samples drawn once; each frame reads them from a seeded random offset, which
  /// is far cheaper than drawing 3 values per pixel per frame and looks the same.
  std::vector<float> noise_pool_;
  cv::Mat3f work_;  ///< reused between frames (no page faults for fresh buffers)
  cv::Mat3b out_;
};

}  // namespace houghloc
