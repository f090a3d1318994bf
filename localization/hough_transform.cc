#include "localization/hough_transform.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace houghloc {
namespace {

/// Splits `weight` between the two rows around fractional row `r` (kernel K of step 1).
inline void vote(float* column, int rows, double r, double weight) {
  const double fl = std::floor(r);
  const int j = static_cast<int>(fl);
  const double f = r - fl;
  if (j >= 0 && j < rows) column[j] += static_cast<float>(weight * (1.0 - f));
  if (j + 1 >= 0 && j + 1 < rows) column[j + 1] += static_cast<float>(weight * f);
}

}  // namespace

double WeightedPoints::totalWeight() const {
  double sum = 0.0;
  for (double w : weights) sum += w;
  return sum;
}

int houghRows(double rho_step_m, double rho_max_m) {
  return 2 * static_cast<int>(std::ceil(rho_max_m / rho_step_m - 1e-9)) + 1;
}

HoughTransform::HoughTransform(const HoughConfig& config, double rho_max_m) : config_(config) {
  if (!(config.theta_step_rad > 0.0) || !(config.rho_step_m > 0.0) || !(rho_max_m > 0.0)) {
    throw std::invalid_argument("HoughTransform: theta_step_rad, rho_step_m, rho_max must be > 0");
  }
  num_theta_ = static_cast<int>(std::lround(M_PI / config.theta_step_rad));
  config_.theta_step_rad = M_PI / num_theta_;  // an exact divisor of pi keeps the wrap exact
  num_rho_ = houghRows(config.rho_step_m, rho_max_m);
  centre_row_ = (num_rho_ - 1) / 2;
  cos_.resize(num_theta_);  // float: see addPoint
  sin_.resize(num_theta_);
  for (int i = 0; i < num_theta_; ++i) {
    cos_[i] = static_cast<float>(std::cos(theta(i)));
    sin_[i] = static_cast<float>(std::sin(theta(i)));
  }
  cells_.assign(static_cast<std::size_t>(num_theta_) * num_rho_, 0.0f);
}

void HoughTransform::addPoint(const Eigen::Vector2d& p, double weight) {
  if (!p.allFinite() || !std::isfinite(weight) || cells_.empty()) return;
  // Single precision is plenty for a row index (|rho| / rho_step < 1e4).
  const float inv_step = static_cast<float>(1.0 / config_.rho_step_m);
  const float x = static_cast<float>(p.x()) * inv_step, y = static_cast<float>(p.y()) * inv_step;
  const float centre = static_cast<float>(centre_row_);
  const float last = num_rho_ - 1.0f;
  const float w = static_cast<float>(weight);
  float* column = cells_.data();
  for (int i = 0; i < num_theta_; ++i, column += num_rho_) {
    const float r = x * cos_[i] + y * sin_[i] + centre;
    if (r >= 0.0f && r < last) {  // the usual case: both rows inside, no floor needed
      const int j = static_cast<int>(r);
      const float f = r - j;
      column[j] += w - w * f;
      column[j + 1] += w * f;
    } else {
      vote(column, num_rho_, r, weight);
    }
  }
}

void HoughTransform::addPoints(const WeightedPoints& points) {
  if (cells_.empty()) return;
  // Column by column (one column stays in L1 while every point votes into it; point by point
  // would sweep the whole accumulator per point). Per column, a loop the compiler vectorises
  // computes every point's row and the two shares of its vote, then a plain loop adds them;
  // a column where some point falls outside the rows takes addPoint's per-point path instead.
  // Same arithmetic and, per cell, the same order of additions as addPoint, so the result is
  // identical.
  const float inv_step = static_cast<float>(1.0 / config_.rho_step_m);
  std::vector<float> xs, ys, ws;
  std::vector<double> weights;
  xs.reserve(points.size());
  ys.reserve(points.size());
  ws.reserve(points.size());
  weights.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector2d& p = points.points[k];
    const double weight = points.weights[k];
    if (!p.allFinite() || !std::isfinite(weight)) continue;
    xs.push_back(static_cast<float>(p.x()) * inv_step);
    ys.push_back(static_cast<float>(p.y()) * inv_step);
    ws.push_back(static_cast<float>(weight));
    weights.push_back(weight);
  }
  const int n = static_cast<int>(xs.size());
  std::vector<float> rows(n), lower(n), upper(n);
  std::vector<int> first(n);
  const float centre = static_cast<float>(centre_row_);
  const float last = num_rho_ - 1.0f;
  float* column = cells_.data();
  for (int i = 0; i < num_theta_; ++i, column += num_rho_) {
    const float c = cos_[i], s = sin_[i];
    int outside = 0;
    for (int k = 0; k < n; ++k) {
      const float r = xs[k] * c + ys[k] * s + centre;
      rows[k] = r;
      outside += (r < 0.0f) | (r >= last);  // r is finite: the inside test of addPoint
      // Clamped before the conversion, so that no row out of int's range is converted; inside
      // the rows (the only case these shares are used) the clamp changes nothing.
      const int j = static_cast<int>(std::min(std::max(r, 0.0f), last));
      const float f = r - j;
      const float w = ws[k];
      first[k] = j;
      lower[k] = w - w * f;
      upper[k] = w * f;
    }
    if (outside == 0) {
      for (int k = 0; k < n; ++k) {
        column[first[k]] += lower[k];
        column[first[k] + 1] += upper[k];
      }
      continue;
    }
    for (int k = 0; k < n; ++k) {
      const float r = rows[k];
      if (r >= 0.0f && r < last) {
        column[first[k]] += lower[k];
        column[first[k] + 1] += upper[k];
      } else {
        vote(column, num_rho_, r, weights[k]);
      }
    }
  }
}

std::vector<float> houghColumn(const WeightedPoints& points, double theta_rad, double rho_step_m,
                               double rho_max_m) {
  const int rows = houghRows(rho_step_m, rho_max_m);
  const int centre = (rows - 1) / 2;
  std::vector<float> column(rows, 0.0f);
  const double c = std::cos(theta_rad) / rho_step_m, s = std::sin(theta_rad) / rho_step_m;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector2d& p = points.points[k];
    vote(column.data(), rows, p.x() * c + p.y() * s + centre, points.weights[k]);
  }
  return column;
}

}  // namespace houghloc
