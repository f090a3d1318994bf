#include "vision/line_spots.h"

#include <algorithm>
#include <cmath>

#include "vision/ball_spots.h"
#include "vision/line_continuation.h"
#include "vision/pixel_access.h"
#include "vision/scanline.h"
#include "vision/spot_thresholds.h"

namespace houghloc {
namespace {

class SpotScanner {
 public:
  SpotScanner(const FieldColor& color, const LineWidthModel& widths, const LineWidthModel* widest,
              const LineSpotConfig& config, cv::Size image, std::vector<LineSpot>* spots,
              LineSpotStats* stats)
      : color_(color),
        widths_(widths),
        widest_(widest),
        config_(config),
        thresholds_(color, widths, config, image),
        spots_(spots),
        stats_(stats) {
    dark_luma_ = static_cast<int>(config.dark_luma_ratio * color.luma_median);
    const int whole_turf = noiseThreshold(color.luma_sigma, color.texture_sigma, config);
    ball_classes_.patch_luma = static_cast<int>(color.luma_median) + whole_turf / 4;
    ball_classes_.patch_chroma = static_cast<float>(
        config.ball.patch_grey_ratio * std::hypot(color.r - 1.0 / 3.0, color.g - 1.0 / 3.0));
  }

  std::size_t spotCount() const { return spots_->size(); }

  template <typename Run>
  void scan(const Scanline<Run>& line) const {
    // The scan asks the least a line's run may rise (that of a saturated peak; check() tests
    // the peak). A row's pixels share its row's thresholds, and so do all pixels of a frame whose
    // rows all have the same.
    if (line.dv == 0 || thresholds_.uniform()) {
      const SpotThresholds::ByLuma& by_luma = thresholds_.saturatedByLuma(line.v0);
      scanWith(line, [&](int background, int) { return by_luma[static_cast<size_t>(background)]; });
    } else {
      scanWith(line, [&](int background, int i) {
        return thresholds_.saturated(background, line.v0 + line.dv * i);
      });
    }
  }

  /// Drops the spots from index `first` on whose run does not go on in the scanlines beside
  /// them (line_continuation.h) or that lie on a ball (ball_spots.h). `buffer` must not be the
  /// one the scanline was decoded into.
  template <typename Pixels>
  void dropNonLineSpots(const Pixels& pixels, std::size_t first, RunBuffer* buffer) const {
    std::size_t kept = first;
    for (std::size_t i = first; i < spots_->size(); ++i) {
      const LineSpot spot = (*spots_)[i];
      const int row = static_cast<int>(spot.pixel.y() + 0.5f);        // a pixel: not negative
      if (!continuesBeside(pixels, spot, thresholds_.shade(row) / 2,  // the lower level's
                           RunBounds{color_, dark_luma_}, config_.continuation, buffer)) {
        reject(spot.pixel, SpotRejection::kCompactBlob, &LineSpotStats::compact_blob);
      } else if (onBall(pixels, spot, ballRadiusPx(spot), ball_classes_, config_.ball)) {
        reject(spot.pixel, SpotRejection::kOnBall, &LineSpotStats::on_ball);
      } else {
        (*spots_)[kept++] = spot;
      }
    }
    spots_->resize(kept);
  }

 private:
  /// The scan of scan(): runs rising over the pixel two back by threshold(background luma,
  /// index of the background pixel), each checked as a line's.
  template <typename Run, typename Threshold>
  void scanWith(const Scanline<Run>& line, Threshold&& threshold_at) const {
    constexpr int kEdgeGap = 2;  // compare with the pixel two back: tolerates one blurred pixel
    int i = kEdgeGap;
    while (i < line.n) {
      const int background = line.luma(i - kEdgeGap);
      const int threshold = threshold_at(background, i - kEdgeGap);
      if (line.luma(i) - background < threshold) {
        ++i;
        continue;
      }
      // A rise from something dark is no line's edge, and all that is brighter than the dark
      // pixel would pass for its run (LineSpotConfig::dark_run_turf_px): it ends at the turf.
      const bool from_dark = background < dark_luma_;
      int end = i;
      int peak = i;
      while (end < line.n && line.luma(end) - background >= threshold / 2 &&
             !(from_dark && turfRun(line, end))) {
        if (line.luma(end) > line.luma(peak)) peak = end;
        ++end;
      }
      check(line, i - kEdgeGap, peak, end);
      i = end + 1;
    }
  }

  /// Whether the pixels from `from` on start a run of turf (dark_run_turf_px; the scanline's
  /// end may cut it short): the end of a dark object's run. More than a pixel or two, since
  /// grey pixels inside a robot pass for turf too.
  template <typename Run>
  bool turfRun(const Scanline<Run>& line, int from) const {
    for (int k = from; k < std::min(line.n, from + config_.dark_run_turf_px); ++k) {
      if (!color_.isField(line.at(k))) return false;
    }
    return true;
  }

  /// The radius (px) a ball at the spot has in the image: its radius over the ground's metres
  /// per pixel across the viewing direction there.
  double ballRadiusPx(const LineSpot& spot) const {
    const float across = widths_.metresPerPx(spot.pixel.x(), spot.pixel.y()).x();
    return across > 0.f ? config_.ball.radius_m / across : 0.0;
  }

  /// Ramp length (px) of the edge between the peak and the background along dir: the contrast
  /// over the steepest two-pixel luma step. Paint ends at a sharp edge (blur and anti-aliasing
  /// spread it over a few px); the shading of a round bar (the goal frame lying on the ground)
  /// fades out over a good part of its width.
  template <typename Run>
  static float edgeRamp(const Scanline<Run>& line, int peak, int dir, int background) {
    int k = peak, steepest = 0;
    while (k + 2 * dir >= 0 && k + 2 * dir < line.n && line.luma(k) > background) {
      steepest = std::max(steepest, line.luma(k) - line.luma(k + 2 * dir));
      k += dir;
    }
    const int contrast = line.luma(peak) - background;
    return steepest > 0 ? 2.f * contrast / steepest : static_cast<float>(line.n);
  }

  /// Whether the run's peak adds white light over the turf on both sides of the run (its width,
  /// checked against LineSpotConfig::max_blend_width_px once measured, must be a thin line's).
  template <typename Run>
  bool thinWhite(const Scanline<Run>& line, int before, int peak, int after) const {
    if (config_.max_blend_width_px <= 0.0) return false;
    const uchar *a = line.at(before), *b = line.at(after);
    return color_.isField(a) && color_.isField(b) && color_.addsWhite(line.at(peak), a, b);
  }

  /// Turf within `count` px, with nothing dark on the way: a white ball patch is followed by a
  /// black one before the turf, a line edge only by its anti-aliased blend. Then `beside` px of
  /// turf beyond it (the image border may cut them short): a line lies on the field, so turf
  /// goes on beside it, while the rim of a robot's leg or a ball patch next to a black one is
  /// bounded by a pixel or two that pass for turf (grey, tinted green by the field) and then
  /// by more of the object.
  template <typename Run>
  bool greenWithin(const Scanline<Run>& line, int from, int dir, int count, int beside,
                   int paint_luma) const {
    for (int k = 0; k < count; ++k) {
      const int idx = from + dir * k;
      if (idx < 0 || idx >= line.n) return false;
      // Dark first: the chromaticity of dark pixels is noisy, so a robot's black joints or
      // shorts next to its white arm can pass for turf.
      if (line.luma(idx) < dark_luma_) return false;
      if (color_.isField(line.at(idx))) return turfBeside(line, idx, dir, beside, paint_luma);
    }
    return false;
  }

  /// At least half of the `count` px from `from` on are turf or as bright as the line itself
  /// (`paint_luma`: another line meeting this one at a junction or crossing).
  template <typename Run>
  bool turfBeside(const Scanline<Run>& line, int from, int dir, int count, int paint_luma) const {
    int seen = 0, turf = 0;
    for (int k = 0; k < count; ++k) {
      const int idx = from + dir * k;
      if (idx < 0 || idx >= line.n) break;
      ++seen;
      const int luma = line.luma(idx);
      turf += luma >= paint_luma || (luma >= dark_luma_ && color_.isField(line.at(idx)));
    }
    return 2 * turf >= seen;
  }

  template <typename Run>
  void reject(const Scanline<Run>& line, int peak, SpotRejection reason,
              int LineSpotStats::*counter) const {
    reject(Eigen::Vector2f(static_cast<float>(line.u0 + line.du * peak),
                           static_cast<float>(line.v0 + line.dv * peak)),
           reason, counter);
  }

  void reject(const Eigen::Vector2f& pixel, SpotRejection reason,
              int LineSpotStats::*counter) const {
    if (!stats_) return;
    ++(stats_->*counter);
    if (config_.keep_rejected) stats_->rejected.push_back({pixel, reason});
  }

  template <typename Run>
  void check(const Scanline<Run>& line, int before, int peak, int end) const {
    if (stats_) ++stats_->candidates;
    const int after = std::min(line.n - 1, end + 1);
    const int peak_luma = line.luma(peak);
    const int background_before = line.luma(before), background_after = line.luma(after);
    // Both sides must clear the threshold of the brighter side's light (the scan tested the
    // rise over `before` against its own).
    const int threshold = thresholds_.forPeak(std::max(background_before, background_after),
                                              line.v0 + line.dv * peak, peak_luma);
    if (peak_luma - background_after < threshold || peak_luma - background_before < threshold ||
        end >= line.n) {
      reject(line, peak, SpotRejection::kNotGreenBounded, &LineSpotStats::not_green_bounded);
      return;
    }
    // A peak that is not white itself may be a thin line's, white by the light it adds.
    const bool whitish = color_.isWhitish(line.at(peak));
    if (!whitish && !thinWhite(line, before, peak, after)) {
      reject(line, peak, SpotRejection::kNotWhite, &LineSpotStats::not_white);
      return;
    }
    const float level = 0.5f * (peak_luma + 0.5f * (background_before + background_after));
    const float left = levelCrossing(line, peak, -1, level),
                right = levelCrossing(line, peak, +1, level);
    const float centre = 0.5f * (left + right), width = right - left;
    const float u = line.u0 + line.du * centre, v = line.v0 + line.dv * centre;
    const Eigen::Vector2f expected_xy = widths_.expectedPx(u, v);
    const float expected = line.dv != 0 ? expected_xy.y() : expected_xy.x();
    float widest = 0.f;
    if (widest_) {
      const Eigen::Vector2f widest_xy = widest_->expectedPx(u, v);
      widest = line.dv != 0 ? widest_xy.y() : widest_xy.x();
    }
    if (!whitish && width > config_.max_blend_width_px) {
      reject(line, peak, SpotRejection::kNotWhite, &LineSpotStats::not_white);
      return;
    }
    switch (compareLineWidth(width, expected, config_, widest)) {
      case WidthFit::kTooWide:
        reject(line, peak, SpotRejection::kTooWide, &LineSpotStats::too_wide);
        if (stats_ && stats_->too_wide_runs.size() < LineSpotStats::kMaxTooWideRuns) {
          stats_->too_wide_runs.push_back({{u, v}, width, expected, line.dv != 0});
        }
        return;
      case WidthFit::kTooNarrow:
        reject(line, peak, SpotRejection::kTooNarrow, &LineSpotStats::too_narrow);
        return;
      case WidthFit::kLine:
        break;
    }
    const float max_ramp = static_cast<float>(
        std::max(config_.max_edge_ramp_px, config_.max_edge_ramp_ratio * expected));
    if (edgeRamp(line, peak, -1, background_before) > max_ramp ||
        edgeRamp(line, peak, +1, background_after) > max_ramp) {
      reject(line, peak, SpotRejection::kSoftEdge, &LineSpotStats::soft_edge);
      return;
    }
    const int gap =
        config_.green_gap_px + static_cast<int>(config_.green_gap_width_share * expected + 0.5);
    const int beside = std::max(config_.min_turf_beside_px,
                                static_cast<int>(config_.turf_beside_width_share * expected + 0.5));
    const int paint = peak_luma - threshold;
    if (!greenWithin(line, static_cast<int>(std::floor(left)), -1, gap + 1, beside, paint) ||
        !greenWithin(line, static_cast<int>(std::ceil(right)), +1, gap + 1, beside, paint)) {
      reject(line, peak, SpotRejection::kNotGreenBounded, &LineSpotStats::not_green_bounded);
      return;
    }
    spots_->push_back({{u, v}, width, expected, line.dv != 0});
  }

  const FieldColor& color_;
  const LineWidthModel& widths_;
  const LineWidthModel* widest_;  ///< none: the pose's pitch is taken as exact
  const LineSpotConfig& config_;
  SpotThresholds thresholds_;
  std::vector<LineSpot>* spots_;
  LineSpotStats* stats_;
  int dark_luma_ = 0;
  BallClasses ball_classes_{color_, 0, 0.f};
};

/// Scans the grid's columns, then its rows, each stretch below the boundary and above the
/// robot's body, into the scanner's spots; each scanline's spots are checked
/// against the scanlines beside them before the next scanline is read.
template <typename Pixels>
void scanGrid(const Pixels& pixels, const FieldBoundary& boundary, const ScanGrid& grid,
              const SpotScanner& scanner) {
  RunBuffer buffer;         // one scanline's decoded pixels (formats not read in place)
  RunBuffer beside_buffer;  // ... and those of the scanlines beside a spot
  for (const ScanGrid::Column& column : grid.columns) {
    const int end = std::min(column.v_end, static_cast<int>(boundary.bodyRowAt(column.u)));
    const int n = end - column.v_begin;
    if (n < 4) continue;
    const std::size_t first = scanner.spotCount();
    scanner.scan(scanline(pixels.columnRun(column.u, column.v_begin, n, &buffer), n, column.u,
                          column.v_begin, 0, 1));
    scanner.dropNonLineSpots(pixels, first, &beside_buffer);
  }
  for (int v : grid.rows) {
    // Scan each stretch of the row that lies below the boundary.
    int u = 0;
    while (u < pixels.cols()) {
      const auto field = [&](int col) {
        return boundary.rowAt(col) <= v && v < boundary.bodyRowAt(col);
      };
      while (u < pixels.cols() && !field(u)) ++u;
      const int begin = u;
      while (u < pixels.cols() && field(u)) ++u;
      if (u - begin >= 4) {
        const std::size_t first = scanner.spotCount();
        scanner.scan(
            scanline(pixels.rowRun(begin, v, u - begin, &buffer), u - begin, begin, v, 1, 0));
        scanner.dropNonLineSpots(pixels, first, &beside_buffer);
      }
    }
  }
}

}  // namespace

WidthFit compareLineWidth(double width_px, double expected_px, const LineSpotConfig& config,
                          double widest_px) {
  const double widest = std::max(expected_px, widest_px);
  if (width_px > config.max_width_ratio * widest + config.width_tolerance_px) {
    return WidthFit::kTooWide;
  }
  if (width_px < config.min_width_ratio * expected_px - 1.0 || expected_px <= 0.0) {
    return WidthFit::kTooNarrow;
  }
  return WidthFit::kLine;
}

std::vector<LineSpot> detectLineSpots(const cv::Mat& image, const FieldColor& color,
                                      const FieldBoundary& boundary, const ScanGrid& grid,
                                      const LineWidthModel& widths, const LineSpotConfig& config,
                                      LineSpotStats* stats, const LineWidthModel* widest) {
  std::vector<LineSpot> spots;
  if (!color.valid || !boundary.found) return spots;
  const SpotScanner scanner(color, widths, widest, config, image.size(), &spots, stats);
  visitPixels(image, [&](const auto& pixels) { scanGrid(pixels, boundary, grid, scanner); });
  return spots;
}

}  // namespace houghloc
