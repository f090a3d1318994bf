#include "vision/field_top_pitch.h"

#include <algorithm>
#include <cmath>

#include "vision/pixel_access.h"

namespace houghloc {
namespace {

/// Turf as bright as the turf below the horizon: the field colour's chromaticity test leaves
/// dark pixels much room (their chromaticity is noisy), and dark curtains, walls and crowds
/// beyond the border pass it.
bool isBrightTurf(const uchar* bgr, const FieldColor& color, const FieldTopPitchConfig& config) {
  return color.isField(bgr) && FieldColor::luma(bgr) >= config.min_luma_ratio * color.luma_median;
}

/// The top row of the turf that column u shows at its start row, followed upwards across gaps
/// of at most config.max_gap_px; -1 when the start row is not turf.
template <typename Pixels>
int turfTopAbove(const Pixels& pixels, const FieldColor& color, int u, int start_row,
                 const FieldTopPitchConfig& config) {
  const int step = std::max(1, config.row_step_px);
  const int first = std::min(start_row, pixels.rows() - 1);
  if (first < 0 || !isBrightTurf(pixels.at(u, first).data(), color, config)) return -1;
  int top = first;
  for (int v = first - step; v >= 0 && top - v <= config.max_gap_px + step; v -= step) {
    if (isBrightTurf(pixels.at(u, v).data(), color, config)) top = v;
  }
  return top;
}

}  // namespace

std::optional<double> pitchToSeeFieldTop(const cv::Mat& image, const FieldColor& color,
                                         const CameraModel& camera,
                                         const std::vector<int>& start_rows,
                                         const FieldTopPitchConfig& config) {
  if (!config.enabled || !color.valid || image.empty()) return std::nullopt;
  if (start_rows.size() != static_cast<size_t>(image.cols)) return std::nullopt;
  // Per column the pitch that puts the turf's top on the horizon. Pitching the camera by delta
  // turns every ray about the horizontal axis across the camera's heading, so a ray with the
  // components `ahead` (along the heading, horizontal) and `up` reaches the horizontal at
  // delta = atan2(up, ahead): the angle above the horizontal for the centre column, more for
  // the others (exact without roll).
  const double yaw = camera.pose().yaw;
  std::vector<double> rises;
  visitPixels(image, [&](const auto& pixels) {
    for (int u = 0; u < image.cols; u += std::max(1, config.column_step_px)) {
      const int top = turfTopAbove(pixels, color, u, start_rows[static_cast<size_t>(u)], config);
      if (top < 0) continue;
      const Eigen::Vector3d ray = camera.pixelRay(u, top);
      const double ahead = ray.x() * std::cos(yaw) + ray.y() * std::sin(yaw);
      if (ray.allFinite() && ahead > 0.0) rises.push_back(std::atan2(ray.z(), ahead));
    }
  });
  const long risen = std::count_if(rises.begin(), rises.end(),
                                   [&](double rise) { return rise >= config.min_rise_rad; });
  if (rises.empty() || static_cast<double>(risen) < config.min_share * rises.size()) {
    return std::nullopt;
  }
  const size_t k =
      std::min(rises.size() - 1, static_cast<size_t>(std::clamp(config.quantile, 0.0, 1.0) *
                                                     static_cast<double>(rises.size())));
  std::nth_element(rises.begin(), rises.begin() + static_cast<long>(k), rises.end());
  const double offset = rises[k] + config.border_depression_rad;
  if (!std::isfinite(offset) || offset > config.max_offset_rad) return std::nullopt;
  return offset;
}

}  // namespace houghloc
