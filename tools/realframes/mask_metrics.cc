#include "tools/realframes/mask_metrics.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc.hpp>

namespace houghloc {
namespace {

/// Distance (px) of every pixel to the nearest non-zero pixel of `mask`.
cv::Mat distanceTo(const cv::Mat& mask) {
  cv::Mat inverted = mask == 0, distance;
  cv::distanceTransform(inverted, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance;
}

}  // namespace

MaskMetrics maskMetrics(const cv::Mat& labels, const std::vector<Eigen::Vector2f>& pixels,
                        double precision_px, double recall_px) {
  MaskMetrics m;
  const cv::Mat line = labels == 1;
  const cv::Mat to_line = distanceTo(line);
  cv::Mat point_mask = cv::Mat::zeros(labels.size(), CV_8U);
  int on_line = 0;
  for (const Eigen::Vector2f& p : pixels) {
    const int u = static_cast<int>(std::lround(p.x())), v = static_cast<int>(std::lround(p.y()));
    if (u < 0 || v < 0 || u >= labels.cols || v >= labels.rows) continue;
    ++m.points;
    point_mask.at<uchar>(v, u) = 255;
    if (to_line.at<float>(v, u) <= precision_px) {
      ++on_line;
    } else if (labels.at<uchar>(v, u) == 2) {
      ++m.off_line_on_field;
    }
  }
  if (m.points > 0) m.precision = static_cast<double>(on_line) / m.points;
  cv::Mat skeleton;
  cv::ximgproc::thinning(line, skeleton, cv::ximgproc::THINNING_ZHANGSUEN);
  const cv::Mat to_point = m.points > 0 ? distanceTo(point_mask) : cv::Mat();
  int covered = 0;
  for (int v = 0; v < skeleton.rows; ++v) {
    for (int u = 0; u < skeleton.cols; ++u) {
      if (skeleton.at<uchar>(v, u) == 0) continue;
      ++m.skeleton_pixels;
      if (m.points > 0 && to_point.at<float>(v, u) <= recall_px) ++covered;
    }
  }
  if (m.skeleton_pixels > 0) m.recall = static_cast<double>(covered) / m.skeleton_pixels;
  return m;
}

}  // namespace houghloc
