#include "tools/offline/trajectory_plot_legend.h"

#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "tools/offline/trajectory_plot.h"

namespace houghloc {
namespace {

constexpr int kPanelWidthPx = 340;  // fits the longest label at the legend font size
constexpr double kFont = 0.5;
const cv::Scalar kText(30, 30, 30);

void label(cv::Mat& image, const std::string& text, const cv::Point& at) {
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, kFont, kText, 1, cv::LINE_AA);
}

}  // namespace

void drawKidnapMarker(cv::Mat& image, const cv::Point2d& p) {
  const cv::Point c(static_cast<int>(p.x), static_cast<int>(p.y));
  cv::circle(image, c, 9, kEventColour, 2, cv::LINE_AA);
  cv::line(image, c + cv::Point(-6, -6), c + cv::Point(6, 6), kEventColour, 2, cv::LINE_AA);
  cv::line(image, c + cv::Point(-6, 6), c + cv::Point(6, -6), kEventColour, 2, cv::LINE_AA);
  label(image, "kidnap", c + cv::Point(12, -8));
}

void drawFallMarker(cv::Mat& image, const cv::Point2d& p, bool start) {
  const cv::Point c(static_cast<int>(p.x), static_cast<int>(p.y));
  const int s = start ? 1 : -1;  // start: apex down
  const std::vector<cv::Point> triangle = {c + cv::Point(0, 9 * s), c + cv::Point(-8, -6 * s),
                                           c + cv::Point(8, -6 * s)};
  cv::polylines(image, triangle, true, kEventColour, 2, cv::LINE_AA);
  label(image, start ? "fall" : "up", c + cv::Point(12, start ? -8 : 16));
}

cv::Mat appendLegend(const cv::Mat& plot, const std::vector<std::string>& notes) {
  cv::Mat out;
  cv::copyMakeBorder(plot, out, 0, 0, 0, kPanelWidthPx, cv::BORDER_CONSTANT,
                     plot.at<cv::Vec3b>(0, 0));
  const int x = plot.cols + 10;
  int y = std::max(60, plot.rows / 2 - 260);
  const int step = 30;
  auto line_item = [&](const cv::Scalar& colour, int thickness, const std::string& text) {
    cv::line(out, {x, y - 5}, {x + 30, y - 5}, colour, thickness, cv::LINE_AA);
    label(out, text, {x + 40, y});
    y += step;
  };
  label(out, "Legend", {x, y});
  y += step;
  line_item({0, 0, 0}, 1, "ground truth");
  for (const char* status : {"TRACKING", "AMBIGUOUS", "LOST", "INITIALIZING"}) {
    cv::circle(out, {x + 15, y - 5}, 3, statusColour(status), cv::FILLED, cv::LINE_AA);
    line_item(statusColour(status), 3, std::string("best pose: ") + status);
  }
  cv::circle(out, {x + 15, y - 5}, 4, statusColour("LOST"), 1, cv::LINE_AA);
  label(out, "no pose (ring on the truth)", {x + 40, y});
  y += step;
  cv::ellipse(out, cv::Point(x + 15, y - 5), cv::Size(14, 7), 0, 0, 360, statusColour("TRACKING"),
              2, cv::LINE_AA);
  label(out, "best hypothesis, 2 sigma", {x + 40, y});
  y += step;
  cv::ellipse(out, cv::Point(x + 15, y - 5), cv::Size(14, 7), 0, 0, 360, kAlternativeColour, 2,
              cv::LINE_AA);
  label(out, "other hypotheses", {x + 40, y});
  y += step;
  label(out, "(ellipses every 2 s)", {x + 40, y - 8});
  y += step;
  const cv::Point kidnap(x + 15, y - 5);
  cv::circle(out, kidnap, 9, kEventColour, 2, cv::LINE_AA);
  cv::line(out, kidnap + cv::Point(-6, -6), kidnap + cv::Point(6, 6), kEventColour, 2, cv::LINE_AA);
  cv::line(out, kidnap + cv::Point(-6, 6), kidnap + cv::Point(6, -6), kEventColour, 2, cv::LINE_AA);
  label(out, "kidnap (arrow: from)", {x + 40, y});
  y += step;
  const cv::Point fall(x + 15, y - 5);
  cv::polylines(out,
                std::vector<cv::Point>{fall + cv::Point(0, 9), fall + cv::Point(-8, -6),
                                       fall + cv::Point(8, -6)},
                true, kEventColour, 2, cv::LINE_AA);
  label(out, "fall (start / end)", {x + 40, y});
  y += step + step / 2;
  for (const std::string& note : notes) {
    label(out, note, {x, y});
    y += step * 3 / 4;
  }
  return out;
}

}  // namespace houghloc
