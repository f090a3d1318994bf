#include "tools/drawing/field_top_view.h"

#include <cmath>
#include <iomanip>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>

namespace houghloc {
namespace {

bool finitePositive(double v) { return std::isfinite(v) && v > 0.0; }

std::string metres(double value) {
  std::ostringstream out;
  out << value << " m";
  return out.str();
}

/// The largest of 1, 2, 5 x 10^k metres not longer than `max_m`.
double roundLength(double max_m) {
  double best = 0.01;
  for (int exponent = -2; exponent <= 3; ++exponent) {
    for (double step : {1.0, 2.0, 5.0}) {
      const double length = step * std::pow(10.0, exponent);
      if (length <= max_m) best = length;
    }
  }
  return best;
}

}  // namespace

FieldTopView::FieldTopView(const FieldModel& field, const FieldTopViewConfig& config)
    : field_(field), config_(config) {
  if (!finitePositive(field.field_length) || !finitePositive(field.field_width) ||
      !std::isfinite(field.border_strip_width) || field.border_strip_width < 0.0) {
    throw std::invalid_argument("field size must be positive and finite to draw it");
  }
  if (!finitePositive(config.pixels_per_metre) || config.margin_px < 0) {
    throw std::invalid_argument("pixels_per_metre must be > 0 and margin_px >= 0");
  }
  const double cols = std::ceil(2.0 * field.outerHalfLength() * config.pixels_per_metre);
  const double rows = std::ceil(2.0 * field.outerHalfWidth() * config.pixels_per_metre);
  const double max_side = config.max_side_px - 2.0 * config.margin_px;
  if (cols > max_side || rows > max_side) {
    throw std::invalid_argument("image would be larger than " + std::to_string(config.max_side_px) +
                                " px; lower the scale");
  }
  image_ = cv::Mat(static_cast<int>(rows) + 2 * config.margin_px,
                   static_cast<int>(cols) + 2 * config.margin_px, CV_8UC3, config.background);
}

cv::Point2d FieldTopView::toPixel(const Eigen::Vector2d& p_field) const {
  const double s = config_.pixels_per_metre;
  return {config_.margin_px + (p_field.x() + field_.outerHalfLength()) * s,
          config_.margin_px + (field_.outerHalfWidth() - p_field.y()) * s};
}

Eigen::Vector2d FieldTopView::toField(const cv::Point2d& pixel) const {
  const double s = config_.pixels_per_metre;
  return {(pixel.x - config_.margin_px) / s - field_.outerHalfLength(),
          field_.outerHalfWidth() - (pixel.y - config_.margin_px) / s};
}

void FieldTopView::drawField() {
  const double hx = field_.outerHalfLength(), hy = field_.outerHalfWidth();
  fillPolygons({{{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}}}, config_.carpet);
  const double w = field_.line_width;
  for (const Segment2& s : field_.segments) {
    if (s.a.allFinite() && s.b.allFinite()) drawBand(s.a, s.b, w, config_.lines);
  }
  for (const Arc2& a : field_.arcs) drawArcBand(a, w, config_.lines);
  for (const Mark& m : field_.marks) {
    if (!m.center.allFinite() || !finitePositive(m.size)) continue;
    if (m.shape == MarkShape::kDot) {
      drawDisc(m.center, 0.5 * m.size, config_.lines);
      continue;
    }
    const double h = 0.5 * m.size;
    drawBand(m.center - Eigen::Vector2d(h, 0.0), m.center + Eigen::Vector2d(h, 0.0), w,
             config_.lines);
    drawBand(m.center - Eigen::Vector2d(0.0, h), m.center + Eigen::Vector2d(0.0, h), w,
             config_.lines);
  }
  for (const Goal& g : field_.goals) drawGoal(g);
}

void FieldTopView::drawGoal(const Goal& g) {
  if (!g.center.allFinite() || !finitePositive(g.inner_width) || !finitePositive(g.post_diameter) ||
      !std::isfinite(g.depth)) {
    return;
  }
  // The net lies behind the goal line, away from the field centre.
  const double out = g.center.x() >= 0.0 ? 1.0 : -1.0;
  const double post_y = 0.5 * (g.inner_width + g.post_diameter);
  const Eigen::Vector2d back = g.center + Eigen::Vector2d(out * g.depth, 0.0);
  const double net_width_m = 2.0 / config_.pixels_per_metre;  // a thin outline
  for (double side : {-1.0, 1.0}) {
    const Eigen::Vector2d post = g.center + Eigen::Vector2d(0.0, side * post_y);
    drawBand(post, back + Eigen::Vector2d(0.0, side * post_y), net_width_m, config_.goal);
  }
  drawBand(back + Eigen::Vector2d(0.0, -post_y), back + Eigen::Vector2d(0.0, post_y), net_width_m,
           config_.goal);
  for (double side : {-1.0, 1.0}) {
    drawDisc(g.center + Eigen::Vector2d(0.0, side * post_y), 0.5 * g.post_diameter, config_.goal);
  }
}

void FieldTopView::drawScaleBar() {
  const double length_m = roundLength(0.25 * 2.0 * field_.outerHalfLength());
  const double s = config_.pixels_per_metre;
  const double y = image_.rows - 0.5 * config_.margin_px;
  const cv::Point2d left(config_.margin_px, y), right(config_.margin_px + length_m * s, y);
  const int tick = std::max(3, config_.margin_px / 6);
  cv::line(image_, left, right, config_.text, 2, cv::LINE_AA);
  for (const cv::Point2d& end : {left, right}) {
    cv::line(image_, end - cv::Point2d(0, tick), end + cv::Point2d(0, tick), config_.text, 2,
             cv::LINE_AA);
  }
  const double font = std::max(0.35, config_.margin_px / 80.0);
  cv::putText(image_, metres(length_m), right + cv::Point2d(2 * tick, font * 10.0),
              cv::FONT_HERSHEY_SIMPLEX, font, config_.text, 1, cv::LINE_AA);
}

void FieldTopView::drawAxes() {
  const Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  const cv::Scalar x_colour(40, 40, 230), y_colour(230, 120, 20);
  drawArrow(origin, {1.0, 0.0}, x_colour, "x");
  drawArrow(origin, {0.0, 1.0}, y_colour, "y");
  cv::circle(image_, toPixel(origin) - cv::Point2d(0.5, 0.5), 4, cv::Scalar(40, 40, 230), -1,
             cv::LINE_AA);
}

void FieldTopView::drawTitle(const std::string& title) {
  double font = std::max(0.4, config_.margin_px / 60.0);
  int baseline = 0;
  cv::Size size = cv::getTextSize(title, cv::FONT_HERSHEY_SIMPLEX, font, 1, &baseline);
  if (size.width > image_.cols - 10) {  // shrink a long title to fit rather than clip it
    font *= (image_.cols - 10.0) / size.width;
    size = cv::getTextSize(title, cv::FONT_HERSHEY_SIMPLEX, font, 1, &baseline);
  }
  const cv::Point origin((image_.cols - size.width) / 2, (config_.margin_px + size.height) / 2);
  cv::putText(image_, title, origin, cv::FONT_HERSHEY_SIMPLEX, font, config_.text, 1, cv::LINE_AA);
}

void FieldTopView::drawAll() {
  drawField();
  drawAxes();
  drawScaleBar();
  std::ostringstream title;
  title << (field_.name.empty() ? "field" : field_.name) << ": " << field_.field_length << " x "
        << field_.field_width << " m, lines " << field_.line_width << " m, x -> opponent goal";
  drawTitle(title.str());
}

}  // namespace houghloc
