#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "vision/line_spots.h"

namespace houghloc {

/// A naive reference line detector: fixed HSV thresholds, every few columns, bottom to top, a
/// white run with green on both sides is a line. No field colour estimate, no horizon, no width
/// model: the figures of the real pipeline are printed beside it.
struct ColumnScanConfig {
  int column_step_px = 4;  ///< scan every this many columns
  int green_hue_min = 35;  ///< OpenCV hue (0-180) of "green"
  int green_hue_max = 90;
  int green_min_sat = 50;   ///< 0-255
  int green_min_val = 30;   ///< 0-255
  int white_max_sat = 70;   ///< 0-255
  int white_min_val = 150;  ///< 0-255
  int max_run_px = 40;      ///< longer white runs are not lines (robots, walls)
  int green_gap_px = 4;     ///< green must follow within this many px on both ends of the run
};

/// Image spots (centre of each accepted run; vertical_scan = true, expected_px = 0) of a BGR8
/// image.
std::vector<LineSpot> columnScanSpots(const cv::Mat& bgr, const ColumnScanConfig& config = {});

}  // namespace houghloc
