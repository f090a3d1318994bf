#include "tools/offline/localization_overlay.h"

#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "tools/offline/overlay.h"

namespace houghloc {
namespace {

constexpr double kSampleStepM = 0.05;
constexpr double kMaxRangeM = 12.0;  // farther map samples are dropped: a pixel or less

/// Draws field-frame samples as connected runs of visible pixels.
class PolylinePainter {
 public:
  PolylinePainter(cv::Mat* image, const CameraModel& camera, const Pose2& field_T_robot,
                  const cv::Scalar& colour, int thickness)
      : image_(image),
        camera_(camera),
        robot_T_field_(field_T_robot.inverse()),
        colour_(colour),
        thickness_(thickness) {}

  void add(const Eigen::Vector2d& p_field) {
    const Eigen::Vector2d p_robot = robot_T_field_.transform(p_field);
    std::optional<Eigen::Vector2d> pixel;
    if (p_robot.norm() < kMaxRangeM) pixel = camera_.project({p_robot.x(), p_robot.y(), 0.0});
    // Points far outside the image are cut too: their distorted position is meaningless.
    if (!pixel || pixel->x() < -camera_.width() || pixel->x() > 2 * camera_.width() ||
        pixel->y() < -camera_.height() || pixel->y() > 2 * camera_.height()) {
      flush();
      return;
    }
    run_.emplace_back(static_cast<int>(std::lround(pixel->x() * 16)),
                      static_cast<int>(std::lround(pixel->y() * 16)));
  }
  void flush() {
    if (run_.size() >= 2) {
      cv::polylines(*image_, run_, false, colour_, thickness_, cv::LINE_AA, 4);
    }
    run_.clear();
  }

 private:
  cv::Mat* image_;
  const CameraModel& camera_;
  Pose2 robot_T_field_;
  cv::Scalar colour_;
  int thickness_;
  std::vector<cv::Point> run_;  // 4 fractional bits
};

void drawText(cv::Mat* image, const std::string& text, cv::Point origin) {
  cv::putText(*image, text, origin, cv::FONT_HERSHEY_SIMPLEX, 0.5, {0, 0, 0}, 3, cv::LINE_AA);
  cv::putText(*image, text, origin, cv::FONT_HERSHEY_SIMPLEX, 0.5, {255, 255, 255}, 1, cv::LINE_AA);
}

std::string statusLine(const FrameEstimate& estimate) {
  char text[160];
  if (estimate.hypotheses.empty()) {
    std::snprintf(text, sizeof(text), "%s  no hypothesis", estimate.status.c_str());
  } else {
    const Pose2& best = estimate.hypotheses.front().mean;
    std::snprintf(text, sizeof(text), "%s  x %.2f y %.2f th %.1f deg  w %.2f  %zu hyp",
                  estimate.status.c_str(), best.x, best.y, best.theta * 180.0 / M_PI,
                  estimate.hypotheses.front().weight, estimate.hypotheses.size());
  }
  return text;
}

}  // namespace

void drawProjectedMap(cv::Mat* image, const CameraModel& camera, const FieldModel& field,
                      const Pose2& field_T_robot, const cv::Scalar& colour, int thickness_px) {
  PolylinePainter painter(image, camera, field_T_robot, colour, thickness_px);
  for (const Segment2& s : field.segments) {
    const int steps = std::max(1, static_cast<int>(std::ceil(s.length() / kSampleStepM)));
    for (int i = 0; i <= steps; ++i) painter.add(s.a + (s.b - s.a) * (double(i) / steps));
    painter.flush();
  }
  for (const Arc2& arc : field.arcs) {
    const int steps = std::max(2, static_cast<int>(std::ceil(arc.length() / kSampleStepM)));
    for (int i = 0; i <= steps; ++i) {
      painter.add(arc.pointAt(arc.start_rad + arc.sweep_rad * double(i) / steps));
    }
    painter.flush();
  }
  for (const Mark& mark : field.marks) {  // a cross of two bars (dots drawn the same, small)
    const double h = 0.5 * mark.size;
    for (const Eigen::Vector2d& d : {Eigen::Vector2d(h, 0.0), Eigen::Vector2d(0.0, h)}) {
      painter.add(mark.center - d);
      painter.add(mark.center + d);
      painter.flush();
    }
  }
}

cv::Mat drawLocalizationOverlay(const cv::Mat& bgr, const VisionResult& vision,
                                const CameraModel& camera, const FieldModel& field,
                                const FrameEstimate& estimate,
                                const std::optional<Pose2>& ground_truth) {
  cv::Mat image = drawVisionOverlay(bgr, vision, camera);
  if (ground_truth) drawProjectedMap(&image, camera, field, *ground_truth, {160, 160, 160}, 1);
  if (!estimate.hypotheses.empty()) {
    drawProjectedMap(&image, camera, field, estimate.hypotheses.front().mean, {0, 140, 255}, 2);
  }
  drawText(&image, statusLine(estimate), {8, 18});
  return image;
}

cv::Mat drawMissingFrameOverlay(int width, int height, const std::string& problem,
                                const FrameEstimate& estimate) {
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(40, 40, 40));
  drawText(&image, statusLine(estimate), {8, 18});
  drawText(&image, problem.substr(problem.find_last_of('/') + 1), {8, height / 2});
  return image;
}

}  // namespace houghloc
