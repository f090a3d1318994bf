#include "vision/width_pitch.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace houghloc {
namespace {

/// A run's ray depression below the horizontal (alpha) and the width the pose expects for it.
/// Pitching the camera by delta turns every ray by delta in depression; on a pinhole camera a
/// ground line's width at the same pixel then scales with sin(alpha + delta) / sin(alpha) along a
/// row and with its square along a column (the pixel's angle to the optical axis, and with it
/// the lens' local scale, stays). Roll is left out: the fit is of the pitch only.
struct Run {
  double alpha;     ///< rad
  double expected;  ///< px, at the pose's pitch
  double width;     ///< px, measured
  int power;        ///< 1 along a row, 2 along a column

  /// The width a line has at the run's pixel with the camera pitched by `offset` more; none
  /// where the ray would no longer reach the ground.
  std::optional<double> expectedWith(double offset) const {
    const double pitched = alpha + offset;
    if (pitched <= 0.0 || pitched >= M_PI / 2) return std::nullopt;
    const double scale = std::sin(pitched) / std::sin(alpha);
    return expected * (power == 2 ? scale * scale : scale);
  }
  double misfit(double expected_px) const {
    return std::abs(std::log(std::max(width, 0.5) / expected_px));
  }
};

/// Every `stride`-th of `runs` that reaches the ground, as a Run.
std::vector<Run> runsOf(const CameraModel& camera, const std::vector<LineSpot>& runs,
                        std::size_t stride) {
  std::vector<Run> used;
  for (std::size_t i = 0; i < runs.size(); i += stride) {
    const LineSpot& run = runs[i];
    const Eigen::Vector3d ray = camera.pixelRay(run.pixel.x(), run.pixel.y());
    if (!ray.allFinite() || !(ray.z() < 0.0) || !(run.expected_px > 0.f)) continue;
    used.push_back({std::asin(std::min(1.0, -ray.z())), run.expected_px, run.width_px,
                    run.vertical_scan ? 2 : 1});
  }
  return used;
}

}  // namespace

std::optional<double> fitPitchToWidths(const CameraModel& camera, const std::vector<LineSpot>& runs,
                                       const LineSpotConfig& spots,
                                       const WidthPitchConfig& config) {
  if (!config.enabled || !(config.step_rad > 0.0)) return std::nullopt;
  if (static_cast<int>(runs.size()) < config.min_runs) return std::nullopt;
  const std::vector<Run> used =
      runsOf(camera, runs,
             std::max<std::size_t>(
                 1, runs.size() / static_cast<std::size_t>(std::max(1, config.max_runs))));
  if (static_cast<int>(used.size()) < config.min_runs) return std::nullopt;
  // The offset that gives most runs a line's width; among equally many, the one whose widths
  // fit best (least summed |log(width / expected)| over those runs), since the width tests'
  // wide band passes a run over a range of offsets.
  // At most a quarter turn either way, in at most 10 000 steps: a config typo cannot hang it.
  const double reach = std::min(config.max_offset_rad, M_PI / 2);
  const int steps = static_cast<int>(std::min(1e4, std::floor(reach / config.step_rad)));
  int best_votes = 0;
  double best_misfit = 0.0, best_offset = 0.0;
  for (int k = -steps; k <= steps; ++k) {
    const double offset = k * config.step_rad;
    if (k == 0) continue;  // the pose's own pitch, which found no spot
    int votes = 0;
    double misfit = 0.0;
    for (const Run& run : used) {
      const std::optional<double> expected = run.expectedWith(offset);
      if (!expected || compareLineWidth(run.width, *expected, spots) != WidthFit::kLine) continue;
      ++votes;
      misfit += run.misfit(*expected);
    }
    if (votes > best_votes || (votes == best_votes && votes > 0 && misfit < best_misfit)) {
      best_votes = votes;
      best_misfit = misfit;
      best_offset = offset;
    }
  }
  const bool enough = best_votes >= config.min_runs &&
                      best_votes >= config.min_share * static_cast<double>(used.size());
  if (!enough) return std::nullopt;
  return best_offset;
}

double fitPitchAboveBound(const CameraModel& camera, const std::vector<LineSpot>& spots,
                          double max_offset_rad, const WidthPitchConfig& config) {
  if (!(config.step_rad > 0.0) || !(max_offset_rad > 0.0)) return 0.0;
  const std::vector<Run> used = runsOf(camera, spots, 1);
  const int steps = static_cast<int>(
      std::min(1e4, std::floor(std::min(max_offset_rad, M_PI / 2) / config.step_rad)));
  double best_offset = 0.0, best_misfit = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= steps && !used.empty(); ++k) {
    const double offset = k * config.step_rad;
    double misfit = 0.0;
    for (const Run& run : used) {
      const std::optional<double> expected = run.expectedWith(offset);
      if (expected) misfit += run.misfit(*expected);
    }
    if (misfit < best_misfit) {
      best_misfit = misfit;
      best_offset = offset;
    }
  }
  return best_offset;
}

}  // namespace houghloc
