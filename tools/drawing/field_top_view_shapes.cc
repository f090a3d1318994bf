// Drawing primitives of FieldTopView: filled polygons in field coordinates, with sub-pixel
// precision and anti-aliasing, so sizes in the image are the real ones.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "tools/drawing/field_top_view.h"

namespace houghloc {
namespace {

constexpr int kShift = 4;  // OpenCV fixed-point bits: 1/16 px
constexpr double kOne = 1 << kShift;

/// OpenCV's integer coordinates name pixel centres, toPixel() pixel corners: shift by half.
cv::Point fixedPoint(const cv::Point2d& p) {
  return {static_cast<int>(std::lround((p.x - 0.5) * kOne)),
          static_cast<int>(std::lround((p.y - 0.5) * kOne))};
}

/// Points along an arc, close enough that the chord error stays below a tenth of a pixel.
std::vector<Eigen::Vector2d> arcPoints(const Eigen::Vector2d& center, double radius_m,
                                       double start_rad, double sweep_rad, double px_per_m) {
  const double radius_px = std::max(radius_m * px_per_m, 1.0);
  const double step = 2.0 * std::sqrt(2.0 * 0.1 / radius_px);
  const int n = std::clamp(static_cast<int>(std::ceil(sweep_rad / step)), 8, 4096);
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i <= n; ++i) {
    const double angle = start_rad + sweep_rad * i / n;
    points.push_back(center + radius_m * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  }
  return points;
}

}  // namespace

void FieldTopView::fillPolygons(const std::vector<std::vector<Eigen::Vector2d>>& polygons_field,
                                const cv::Scalar& colour) {
  std::vector<std::vector<cv::Point>> contours;
  for (const auto& polygon : polygons_field) {
    std::vector<cv::Point> contour;
    for (const Eigen::Vector2d& p : polygon) contour.push_back(fixedPoint(toPixel(p)));
    contours.push_back(std::move(contour));
  }
  cv::fillPoly(image_, contours, colour, cv::LINE_AA, kShift);
}

void FieldTopView::drawBand(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double width_m,
                            const cv::Scalar& colour) {
  // A painted line: the rectangle around the centre line, extended by half the width at both
  // ends so that lines meeting at a corner close it.
  const Eigen::Vector2d d = (b - a).normalized() * (0.5 * width_m);
  if (!d.allFinite()) return;
  const Eigen::Vector2d n(-d.y(), d.x());
  fillPolygons({{a - d + n, b + d + n, b + d - n, a - d - n}}, colour);
}

void FieldTopView::drawArcBand(const Arc2& arc, double width_m, const cv::Scalar& colour) {
  if (!arc.center.allFinite() || !(std::isfinite(arc.radius) && arc.radius > 0.0) ||
      !std::isfinite(arc.start_rad) || !(std::isfinite(arc.sweep_rad) && arc.sweep_rad > 0.0)) {
    return;
  }
  const double sweep = std::min(arc.sweep_rad, 2.0 * M_PI);
  const double s = config_.pixels_per_metre;
  std::vector<Eigen::Vector2d> outer =
      arcPoints(arc.center, arc.radius + 0.5 * width_m, arc.start_rad, sweep, s);
  std::vector<Eigen::Vector2d> inner =
      arcPoints(arc.center, std::max(arc.radius - 0.5 * width_m, 0.0), arc.start_rad, sweep, s);
  if (arc.isFullCircle()) {
    fillPolygons({outer, inner}, colour);  // the inner contour makes the hole
    return;
  }
  outer.insert(outer.end(), inner.rbegin(), inner.rend());
  fillPolygons({outer}, colour);
}

void FieldTopView::drawDisc(const Eigen::Vector2d& center, double radius_m,
                            const cv::Scalar& colour) {
  fillPolygons({arcPoints(center, radius_m, 0.0, 2.0 * M_PI, config_.pixels_per_metre)}, colour);
}

void FieldTopView::drawArrow(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                             const cv::Scalar& colour, const std::string& label) {
  const cv::Point2d tip = toPixel(to);
  cv::arrowedLine(image_, fixedPoint(toPixel(from)), fixedPoint(tip), colour, 2, cv::LINE_AA,
                  kShift, 0.15);
  // The label sits a fixed number of pixels beyond the tip, whatever the scale.
  const cv::Point2d direction = tip - toPixel(from);
  const cv::Point2d unit = direction / std::max(cv::norm(direction), 1e-9);
  cv::putText(image_, label, tip + 14.0 * unit + cv::Point2d(-5, 5), cv::FONT_HERSHEY_SIMPLEX, 0.6,
              colour, 2, cv::LINE_AA);
}

void FieldTopView::drawPose(const Pose2& field_T_robot, const cv::Scalar& colour, double radius_m) {
  if (!field_T_robot.isFinite()) return;
  const Eigen::Vector2d center = field_T_robot.translation();
  const Eigen::Vector2d nose = field_T_robot.transform({1.6 * radius_m, 0.0});
  const int radius_fixed = static_cast<int>(std::lround(radius_m * pixelsPerMetre() * kOne));
  cv::circle(image_, fixedPoint(toPixel(center)), radius_fixed, colour, 2, cv::LINE_AA, kShift);
  cv::line(image_, fixedPoint(toPixel(center)), fixedPoint(toPixel(nose)), colour, 2, cv::LINE_AA,
           kShift);
}

void FieldTopView::drawCovarianceEllipse(const Eigen::Vector2d& mean, const Eigen::Matrix2d& cov,
                                         const cv::Scalar& colour, double sigma) {
  if (!mean.allFinite() || !cov.allFinite()) return;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(0.5 * (cov + cov.transpose()));
  const Eigen::Vector2d variances = eigen.eigenvalues().cwiseMax(0.0);
  const Eigen::Vector2d major = eigen.eigenvectors().col(1);
  const double s = sigma * pixelsPerMetre() * kOne;
  const cv::Size axes(static_cast<int>(std::lround(s * std::sqrt(variances(1)))),
                      static_cast<int>(std::lround(s * std::sqrt(variances(0)))));
  // The image's y axis points down, so angles turn the other way.
  const double angle_deg = -std::atan2(major.y(), major.x()) * 180.0 / M_PI;
  cv::ellipse(image_, fixedPoint(toPixel(mean)), axes, angle_deg, 0.0, 360.0, colour, 2,
              cv::LINE_AA, kShift);
}

void FieldTopView::drawPolyline(const std::vector<Eigen::Vector2d>& points_field,
                                const cv::Scalar& colour, int thickness_px) {
  std::vector<cv::Point> points;
  for (const Eigen::Vector2d& p : points_field) {
    if (p.allFinite()) points.push_back(fixedPoint(toPixel(p)));
  }
  if (points.size() >= 2) {
    cv::polylines(image_, points, false, colour, thickness_px, cv::LINE_AA, kShift);
  }
}

}  // namespace houghloc
