#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

namespace houghloc {

/// Agreement of detected point pixels with a hand-labelled line mask (the real set's labels:
/// single channel, 1 = line, 2 = field, 0 = background).
struct MaskMetrics {
  int points = 0;
  double precision = 0.0;  ///< share of points within precision_px of a line pixel
  double recall = 0.0;     ///< share of the line mask's skeleton within recall_px of a point
  int skeleton_pixels = 0;
  int off_line_on_field = 0;  ///< points farther than precision_px from a line pixel, on field
};

/// Distances are Euclidean in pixels; the skeleton is the mask's Zhang-Suen thinning.
MaskMetrics maskMetrics(const cv::Mat& labels, const std::vector<Eigen::Vector2f>& pixels,
                        double precision_px = 3.0, double recall_px = 16.0);

}  // namespace houghloc
