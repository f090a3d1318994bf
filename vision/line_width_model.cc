#include "vision/line_width_model.h"

#include <algorithm>
#include <cmath>

namespace houghloc {

LineWidthModel::LineWidthModel(const CameraModel& camera, double line_width_m,
                               const LineWidthModelConfig& config)
    : line_width_m_(line_width_m),
      cols_(std::max(2, config.grid_cols)),
      rows_(std::max(2, config.grid_rows)),
      width_(static_cast<float>(camera.width())),
      height_(static_cast<float>(camera.height())) {
  const std::vector<double>& horizon = camera.horizonRows();
  horizon_.resize(horizon.size());
  // Columns without a horizon crossing (+-infinity) borrow the nearest finite value's side:
  // -infinity (ground throughout) the lowest finite horizon, +infinity (no ground) a huge row.
  // With no finite value at all (a camera looking steeply down, e.g. the NAO's lower one) the
  // horizon lies far above the image: a virtual one an image height above the top keeps d large,
  // so width / d and width / d^2 interpolate like the slowly varying widths themselves (a horizon
  // just above the top row would make them blow up there).
  float min_horizon = height_, min_finite = 1e6f;
  for (double h : horizon) {
    if (std::isfinite(h)) min_finite = std::min(min_finite, static_cast<float>(h));
  }
  const float ground_horizon = min_finite < 1e6f ? std::min(min_finite, -1.f) : -height_;
  for (size_t u = 0; u < horizon.size(); ++u) {
    const double h = horizon[u];
    horizon_[u] = std::isfinite(h) ? static_cast<float>(h) : (h < 0 ? ground_horizon : 1e6f);
    min_horizon = std::min(min_horizon, horizon_[u]);
  }
  top_ = std::clamp(min_horizon + 2.f, 0.f, height_ - 1.f);
  grid_.assign(static_cast<size_t>(cols_ * rows_), Eigen::Vector2f::Zero());
  // Fill bottom-up so nodes above the horizon copy the valid node below them.
  for (int c = 0; c < cols_; ++c) {
    const float u = (width_ - 1.f) * c / (cols_ - 1);
    Eigen::Vector2f below = Eigen::Vector2f::Zero();
    for (int r = rows_ - 1; r >= 0; --r) {
      const float v = top_ + (height_ - 1.f - top_) * r / (rows_ - 1);
      const float d = v - horizonAt(u);
      const auto px = d > 1.f ? camera.expectedLineWidthPx(u, v, line_width_m) : std::nullopt;
      if (px && std::isfinite(px->x()) && std::isfinite(px->y())) {
        below = {static_cast<float>(px->x()) / d, static_cast<float>(px->y()) / (d * d)};
      }
      grid_[static_cast<size_t>(r * cols_ + c)] = below;
    }
  }
}

float LineWidthModel::horizonAt(float u) const {
  if (horizon_.empty()) return -1e6f;
  const int i = std::clamp(static_cast<int>(u), 0, static_cast<int>(horizon_.size()) - 1);
  return horizon_[static_cast<size_t>(i)];
}

Eigen::Vector2f LineWidthModel::expectedPx(float u, float v) const {
  if (grid_.empty()) return Eigen::Vector2f::Zero();
  const float d = v - horizonAt(u);
  if (d <= 0.f) return Eigen::Vector2f::Zero();
  const float gx = std::clamp(u / (width_ - 1.f) * (cols_ - 1), 0.f, cols_ - 1.001f);
  const float gy = std::clamp((v - top_) / std::max(1.f, height_ - 1.f - top_) * (rows_ - 1), 0.f,
                              rows_ - 1.001f);
  const int c = static_cast<int>(gx), r = static_cast<int>(gy);
  const float fx = gx - c, fy = gy - r;
  const auto at = [&](int rr, int cc) { return grid_[static_cast<size_t>(rr * cols_ + cc)]; };
  const Eigen::Vector2f k = (1 - fy) * ((1 - fx) * at(r, c) + fx * at(r, c + 1)) +
                            fy * ((1 - fx) * at(r + 1, c) + fx * at(r + 1, c + 1));
  return {k.x() * d, k.y() * d * d};
}

Eigen::Vector2f LineWidthModel::metresPerPx(float u, float v) const {
  const Eigen::Vector2f px = expectedPx(u, v);
  const float w = static_cast<float>(line_width_m_);
  return {px.x() > 0.f ? w / px.x() : 1e6f, px.y() > 0.f ? w / px.y() : 1e6f};
}

}  // namespace houghloc
