#include "tools/offline/trajectory_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <opencv2/imgproc.hpp>

#include "tools/offline/evaluation_frames.h"
#include "tools/offline/trajectory_plot_legend.h"

namespace houghloc {
namespace {

constexpr double kEllipseIntervalS = 2.0;  ///< hypotheses' ellipses every this many seconds
constexpr double kJumpM = 0.5;   ///< consecutive poses farther apart are not joined by a line
constexpr int kMaxEllipses = 6;  ///< hypotheses drawn per ellipse frame, best first
/// Ellipses wider than this (1-D or heading-only hypotheses) would cover the field; skipped.
constexpr double kMaxEllipseSigmaM = 1.5;

/// Sub-pixel OpenCV point (4 fractional bits) at a FieldTopView position.
cv::Point fixed(const cv::Point2d& p) {
  return {static_cast<int>(std::lround((p.x - 0.5) * 16.0)),
          static_cast<int>(std::lround((p.y - 0.5) * 16.0))};
}

/// Ground truth as polylines, split where it jumps (a kidnap) or is missing.
std::vector<std::vector<Eigen::Vector2d>> truthPieces(const std::vector<EvaluatedFrame>& frames) {
  std::vector<std::vector<Eigen::Vector2d>> pieces(1);
  for (const EvaluatedFrame& f : frames) {
    if (!f.truth) {
      pieces.emplace_back();
      continue;
    }
    const Eigen::Vector2d p = f.truth->translation();
    if (!pieces.back().empty() && (pieces.back().back() - p).norm() > kJumpM) pieces.emplace_back();
    pieces.back().push_back(p);
  }
  return pieces;
}

void drawEstimates(FieldTopView* view, const std::vector<EvaluatedFrame>& frames) {
  cv::Mat& image = view->image();
  const GaussianPose* previous = nullptr;
  for (const EvaluatedFrame& f : frames) {
    const GaussianPose* best = f.best();
    if (!best) {
      // A frame without a pose: a ring in its status colour on the ground truth.
      if (f.truth && f.estimate) {
        cv::circle(image, fixed(view->toPixel(f.truth->translation())), 4 * 16,
                   statusColour(f.estimate->status), 1, cv::LINE_AA, 4);
      }
      previous = nullptr;
      continue;
    }
    const cv::Scalar colour = statusColour(f.estimate->status);
    const cv::Point2d p = view->toPixel(best->mean.translation());
    if (previous && (previous->mean.translation() - best->mean.translation()).norm() <= kJumpM) {
      cv::line(image, fixed(view->toPixel(previous->mean.translation())), fixed(p), colour, 2,
               cv::LINE_AA, 4);
    }
    cv::circle(image, fixed(p), 2 * 16, colour, cv::FILLED, cv::LINE_AA, 4);
    previous = best;
  }
}

void drawHypotheses(FieldTopView* view, const std::vector<EvaluatedFrame>& frames) {
  double next_s = 0.0;
  const std::int64_t t0 = frames.empty() ? 0 : frames.front().t_us;
  for (const EvaluatedFrame& f : frames) {
    const double t_s = 1e-6 * static_cast<double>(f.t_us - t0);
    if (t_s < next_s || !f.best()) continue;
    next_s = std::floor(t_s / kEllipseIntervalS + 1.0) * kEllipseIntervalS;
    const auto& h = f.estimate->hypotheses;
    for (size_t r = std::min<size_t>(h.size(), kMaxEllipses); r-- > 0;) {
      const Eigen::Matrix2d cov = h[r].covariance.topLeftCorner<2, 2>();
      if (std::sqrt(std::max(cov(0, 0), cov(1, 1))) > kMaxEllipseSigmaM) continue;
      const cv::Scalar colour = r == 0 ? statusColour(f.estimate->status) : kAlternativeColour;
      view->drawCovarianceEllipse(h[r].mean.translation(), cov, colour, 2.0);
      if (r == 0) view->drawPose(h[r].mean, colour, 0.06);
    }
  }
}

void drawEvents(FieldTopView* view, const std::vector<EvaluatedFrame>& frames,
                const std::vector<PlacedEvent>& events) {
  for (const PlacedEvent& e : events) {
    const EvaluatedFrame& f = frames[static_cast<size_t>(e.frame)];
    if (!f.truth) continue;
    const cv::Point2d p = view->toPixel(f.truth->translation());
    if (e.event == "KIDNAP") {
      drawKidnapMarker(view->image(), p);
      // Where the robot was taken from: the last truth before the event frame.
      if (e.frame > 0 && frames[static_cast<size_t>(e.frame) - 1].truth) {
        const cv::Point2d from =
            view->toPixel(frames[static_cast<size_t>(e.frame) - 1].truth->translation());
        cv::arrowedLine(view->image(), fixed(from), fixed(p), kEventColour, 1, cv::LINE_AA, 4,
                        0.05);
      }
    } else {
      drawFallMarker(view->image(), p, e.event == "FALL_START");
    }
  }
}

}  // namespace

FieldTopViewConfig trajectoryPlotViewConfig(const FieldModel& field) {
  FieldTopViewConfig config;
  config.pixels_per_metre = std::clamp(1400.0 / (2.0 * field.outerHalfLength()), 20.0, 150.0);
  config.margin_px = 50;
  config.carpet = {178, 214, 178};  // pale green: status colours and black stay readable
  config.lines = {255, 255, 255};
  return config;
}

cv::Scalar statusColour(const std::string& status) {
  if (status == "TRACKING") return {40, 160, 0};
  if (status == "AMBIGUOUS") return {0, 140, 255};
  if (status == "LOST") return {30, 30, 220};
  return {140, 140, 140};
}

cv::Mat drawTrajectoryPlot(const OfflineContext& context,
                           const std::vector<FrameEstimate>& estimates,
                           const std::vector<std::string>& notes) {
  const FieldModel& field = context.field.value();
  FieldTopView view(field, trajectoryPlotViewConfig(field));
  view.drawField();
  view.drawScaleBar();
  std::vector<PlacedEvent> events;
  const std::vector<EvaluatedFrame> frames = evaluatedFrames(context, estimates, &events);
  drawEstimates(&view, frames);
  drawHypotheses(&view, frames);
  for (const auto& piece : truthPieces(frames)) view.drawPolyline(piece, {0, 0, 0}, 1);
  drawEvents(&view, frames, events);
  std::filesystem::path folder_path =
      std::filesystem::path(context.recording.folder).lexically_normal();
  if (!folder_path.has_filename()) folder_path = folder_path.parent_path();  // "dir/"
  const std::string folder = folder_path.filename().string();
  const double duration_s =
      frames.size() < 2 ? 0.0
                        : 1e-6 * static_cast<double>(frames.back().t_us - frames.front().t_us);
  char span[64];
  std::snprintf(span, sizeof(span), ", %zu frames (%.1f s)", frames.size(), duration_s);
  view.drawTitle((folder.empty() ? context.recording.folder : folder) + " - " + field.name + span);
  return appendLegend(view.image(), notes);
}

}  // namespace houghloc
