#include "tools/realframes/coverage_overlay.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "tools/realframes/groundtruth_metrics.h"
#include "tools/recording/recording.h"

namespace houghloc {
namespace {

/// The pixel of a ground point (robot frame), when the camera sees it.
std::optional<cv::Point> pixelOf(const CameraModel& camera, const Eigen::Vector2d& p_robot) {
  const auto pixel = camera.project({p_robot.x(), p_robot.y(), 0.0});
  if (!pixel || !camera.inImage(*pixel)) return std::nullopt;
  return cv::Point(static_cast<int>(std::lround(pixel->x())),
                   static_cast<int>(std::lround(pixel->y())));
}

}  // namespace

cv::Mat coverageOverlay(const cv::Mat& bgr, const CameraModel& camera,
                        const std::vector<Eigen::Vector2d>& samples_robot,
                        const std::vector<Eigen::Vector2d>& points_robot, double radius_m) {
  cv::Mat out = bgr.clone();
  int covered = 0;
  for (const Eigen::Vector2d& sample : samples_robot) {
    const bool found = countCoveredSamples({sample}, points_robot, radius_m) > 0;
    covered += found;
    if (const auto pixel = pixelOf(camera, sample)) {
      cv::circle(out, *pixel, 2, found ? kCoveredColour : kUncoveredColour, cv::FILLED);
    }
  }
  for (const Eigen::Vector2d& point : points_robot) {
    if (const auto pixel = pixelOf(camera, point)) {
      cv::drawMarker(out, *pixel, kPointColour, cv::MARKER_CROSS, 7, 1);
    }
  }
  char caption[128];
  std::snprintf(caption, sizeof(caption), "cover %d of %zu samples, %zu points", covered,
                samples_robot.size(), points_robot.size());
  cv::putText(out, caption, {8, out.rows - 10}, cv::FONT_HERSHEY_SIMPLEX, 0.5, {0, 0, 0}, 3);
  cv::putText(out, caption, {8, out.rows - 10}, cv::FONT_HERSHEY_SIMPLEX, 0.5, {255, 255, 255}, 1);
  return out;
}

void writeCoverageOverlay(const std::string& path, const cv::Mat& bgr, const CameraModel& camera,
                          const std::vector<Eigen::Vector2d>& samples_robot,
                          const std::vector<Eigen::Vector2d>& points_robot, double radius_m) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (!folder.empty()) std::filesystem::create_directories(folder);
  if (!cv::imwrite(path, coverageOverlay(bgr, camera, samples_robot, points_robot, radius_m))) {
    throw RecordingError("cannot write " + path);
  }
}

}  // namespace houghloc
