#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "vision/field_color.h"

namespace houghloc {

struct FieldBoundaryConfig {
  int column_step_px = 8;    ///< columns sampled for the top of the green region
  int row_step_px = 4;       ///< row spacing of the samples along a column
  int min_green_run = 3;     ///< consecutive green samples that mark the start of the field
  double max_spike_px = 24;  ///< a hull vertex this far above both neighbouring columns' tops
                             ///< (green far beyond the field, e.g. a poster) is dropped
  int max_spike_passes = 4;  ///< hull recomputations for dropped spikes
  int min_body_px = 12;      ///< non-turf reaching the image bottom over at least this many rows
                             ///< is the robot's own body (feet): not scanned ...
  double min_body_width_share = 0.15;  ///< ... when its non-turf run along the bottom row is at
                                       ///< least this share of the width (lines are narrower)
  double body_height_tolerance = 1.3;  ///< a column of such a run reaching higher than this
                                       ///< times the run's median height is a line entering it
};

/// Where the field ends in the image: per column the first row (from the top) of the field.
/// Rows at or below it are field (or things standing on it); rows above are beyond the border.
struct FieldBoundary {
  bool found = false;
  std::vector<float> rows;                  ///< one per column; image height when no field
  std::vector<Eigen::Vector2f> green_tops;  ///< sampled top of the green per column (u, v)
  std::vector<Eigen::Vector2f> hull;        ///< fitted boundary vertices (u, v), left to right

  /// Per column the first row of the robot's own body seen at the image bottom (image height
  /// when none): turf-less rows touching the bottom edge, widened by one sample column.
  std::vector<float> body_rows;

  float rowAt(int u) const { return rows[static_cast<size_t>(u)]; }
  float bodyRowAt(int u) const { return body_rows[static_cast<size_t>(u)]; }
};

/// Finds the top of the green in sparse columns below the start rows (horizon) and fits the
/// upper convex hull of those tops. The field seen from inside is convex in the image (up to
/// lens distortion), and robots or other occluders only push single tops down, so the hull
/// ignores them; isolated tops far above their neighbours are dropped as green clutter beyond
/// the field.
/// image: BGR8 or YUYV (pixel_access.h); YUYV pixels are decoded where sampled.
FieldBoundary detectFieldBoundary(const cv::Mat& image, const FieldColor& color,
                                  const std::vector<int>& start_rows,
                                  const FieldBoundaryConfig& config = {});

}  // namespace houghloc
