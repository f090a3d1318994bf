#pragma once

#include <Eigen/Core>
#include <vector>

#include "vision/camera_model.h"

namespace houghloc {

struct LineWidthModelConfig {
  int grid_cols = 9;  ///< sample columns across the image
  int grid_rows = 8;  ///< sample rows between the horizon (or top) and the bottom
};

/// Expected pixel width of a field line anywhere below the horizon, interpolated from a coarse
/// grid of CameraModel::expectedLineWidthPx() samples. On a pinhole camera the width along a row
/// grows linearly and the width along a column quadratically with the distance below the horizon
/// (1/depth is affine in the image), so the grid stores width / d and width / d^2 (d = rows
/// below the horizon), which vary only slowly; that keeps per-frame cost at a few dozen camera
/// queries instead of one per candidate.
class LineWidthModel {
 public:
  LineWidthModel() = default;
  LineWidthModel(const CameraModel& camera, double line_width_m,
                 const LineWidthModelConfig& config = {});

  /// (x, y): expected extent along the row and along the column at pixel (u, v), px; zero above
  /// the horizon.
  Eigen::Vector2f expectedPx(float u, float v) const;

  /// Ground metres per pixel at (u, v) across (x) and along (y) the viewing direction.
  Eigen::Vector2f metresPerPx(float u, float v) const;

 private:
  float horizonAt(float u) const;

  double line_width_m_ = 0.05;
  int cols_ = 0, rows_ = 0;
  float width_ = 0.f, height_ = 0.f, top_ = 0.f;
  std::vector<float> horizon_;         ///< per image column
  std::vector<Eigen::Vector2f> grid_;  ///< (x / d, y / d^2) at the grid nodes
};

}  // namespace houghloc
