#include "tools/baselines/column_scan.h"

#include <opencv2/imgproc.hpp>

namespace houghloc {
namespace {

enum class Kind : unsigned char { kOther, kGreen, kWhite };

Kind classify(const uchar* hsv, const ColumnScanConfig& c) {
  const int h = hsv[0], s = hsv[1], v = hsv[2];
  if (s <= c.white_max_sat && v >= c.white_min_val) return Kind::kWhite;
  if (h >= c.green_hue_min && h <= c.green_hue_max && s >= c.green_min_sat && v >= c.green_min_val)
    return Kind::kGreen;
  return Kind::kOther;
}

}  // namespace

std::vector<LineSpot> columnScanSpots(const cv::Mat& bgr, const ColumnScanConfig& config) {
  std::vector<LineSpot> spots;
  if (bgr.empty() || bgr.type() != CV_8UC3) return spots;
  cv::Mat hsv;
  cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV);
  std::vector<Kind> column(static_cast<size_t>(bgr.rows));
  for (int u = config.column_step_px / 2; u < bgr.cols; u += std::max(1, config.column_step_px)) {
    for (int v = 0; v < bgr.rows; ++v) column[v] = classify(hsv.ptr<uchar>(v) + 3 * u, config);
    // Bottom to top: last green row below, then a white run, then green within the gap above.
    int last_green = -1;  // row of the nearest green pixel below the current one
    for (int v = bgr.rows - 1; v >= 0; --v) {
      if (column[v] == Kind::kGreen) {
        last_green = v;
        continue;
      }
      if (column[v] != Kind::kWhite || last_green < 0 || last_green - v > config.green_gap_px)
        continue;
      int top = v;
      while (top > 0 && column[top - 1] == Kind::kWhite) --top;
      const int run = v - top + 1;
      int above = top - 1;
      while (above >= 0 && top - above <= config.green_gap_px && column[above] != Kind::kGreen)
        --above;
      if (run <= config.max_run_px && above >= 0 && column[above] == Kind::kGreen) {
        LineSpot spot;
        spot.pixel = {static_cast<float>(u), 0.5f * static_cast<float>(top + v)};
        spot.width_px = static_cast<float>(run);
        spot.vertical_scan = true;
        spots.push_back(spot);
      }
      v = top;  // continue above the run
      last_green = -1;
    }
  }
  return spots;
}

}  // namespace houghloc
