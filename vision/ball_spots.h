#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "vision/field_color.h"
#include "vision/line_spots.h"  // LineSpot, BallConfig
#include "vision/pixel_access.h"

namespace houghloc {

/// How the ball test tells turf and the ball's patches from the rest.
struct BallClasses {
  const FieldColor& color;
  int patch_luma;      ///< pixels darker than this (about the turf's median) ...
  float patch_chroma;  ///< ... and nearer grey than this (chromaticity) are the ball's patches
};

namespace ball_detail {

/// Turf, and not grey: isField allows dark pixels more chroma noise, so the ball's dark grey
/// patches pass it.
inline bool isTurf(const BgrBytes& bgr, const BallClasses& classes) {
  return classes.color.isField(bgr.data()) && !classes.color.isWhitish(bgr.data());
}

/// Grey and about as dark as the turf or darker: the ball's black patches (grey under the field's
/// light). Turf in a shadow keeps most of its colour, and the grey blend at a line's edge is
/// brighter than the turf beside it.
inline bool isPatch(const BgrBytes& bgr, const BallClasses& classes) {
  return FieldColor::luma(bgr.data()) < classes.patch_luma &&
         FieldColor::isNearGrey(bgr.data(), classes.patch_chroma);
}

/// Turf in a row that ends a blob: a pixel or two at the edge of a black patch pass for turf
/// (the colour fringe of the camera's demosaicing).
constexpr int kTurfRun = 3;

/// Pixels from (u, v) in direction (du, dv) up to the first of kTurfRun turf pixels in a row; -1
/// when `limit` px pass first or the image ends (the blob goes on or cannot be seen whole).
/// Reads every kTurfRun-th pixel, and the neighbours of those that are turf: every run of
/// kTurfRun pixels holds exactly one of them, so the answer is that of reading every pixel, for
/// about a third of the reads along a line (the walk every line spot pays).
template <typename Pixels>
int runToTurf(const Pixels& pixels, int u, int v, int du, int dv, int limit,
              const BallClasses& classes) {
  static_assert(kTurfRun == 3, "the runs holding a sample are listed for runs of 3");
  const int last = limit + kTurfRun - 1;  // a run must end here at the latest
  const auto inside = [&](int k) {
    const int x = u + du * k, y = v + dv * k;
    return x >= 0 && y >= 0 && x < pixels.cols() && y < pixels.rows();
  };
  const auto turf = [&](int k) {
    return k <= last && inside(k) && isTurf(pixels.at(u + du * k, v + dv * k), classes);
  };
  for (int m = kTurfRun; m <= last; m += kTurfRun) {
    if (!inside(m)) return -1;  // the image ends before any run that is not yet ruled out
    if (!turf(m)) continue;
    // The runs holding m, earliest first: [m-2, m], [m-1, m+1], [m, m+2].
    const bool before = turf(m - 1);
    if (before && turf(m - 2)) return m - 2;
    if (!turf(m + 1)) continue;
    if (before) return m - 1;
    if (turf(m + 2)) return m;
  }
  return -1;
}

}  // namespace ball_detail

/// Whether `spot` lies on a ball: a round blob that is not turf, of about the radius the ball
/// has at that distance (`radius_px`, from BallConfig::radius_m and the ground scale there),
/// holding dark or grey patches, with turf around it. The chords through the spot along the row
/// and the column give the blob's centre (a chord's midpoint lies on the diameter across it);
/// from the centre the blob must end in turf in all four directions within the radius range and
/// about as far in each. A line runs on beyond the range along its direction, a penalty mark or a
/// line crossing has no patches and no turf ring, so neither is taken for a ball.
template <typename Pixels>
bool onBall(const Pixels& pixels, const LineSpot& spot, double radius_px,
            const BallClasses& classes, const BallConfig& config) {
  using ball_detail::isPatch;
  using ball_detail::isTurf;
  using ball_detail::runToTurf;
  // A ball larger than the image cannot be judged (and its walks would not fit an int).
  if (!config.enabled || !(radius_px >= config.min_radius_px) ||
      radius_px > pixels.cols() + pixels.rows()) {
    return false;
  }
  const int limit = static_cast<int>(std::ceil(2.0 * config.max_radius_ratio * radius_px));
  const int u = static_cast<int>(std::lround(spot.pixel.x()));
  const int v = static_cast<int>(std::lround(spot.pixel.y()));
  // The chords along the row and the column, the one along the line first (across the
  // scanline that found the spot): a line runs on past `limit` there, which ends the test after
  // that one walk.
  int left = -1, right = -1, up = -1, down = -1;
  const auto rowChord = [&] {
    left = runToTurf(pixels, u, v, -1, 0, limit, classes);
    right = left < 0 ? -1 : runToTurf(pixels, u, v, 1, 0, limit, classes);
    return right >= 0;
  };
  const auto columnChord = [&] {
    up = runToTurf(pixels, u, v, 0, -1, limit, classes);
    down = up < 0 ? -1 : runToTurf(pixels, u, v, 0, 1, limit, classes);
    return down >= 0;
  };
  if (spot.vertical_scan ? !(rowChord() && columnChord()) : !(columnChord() && rowChord())) {
    return false;
  }
  const int cu = u + (right - left) / 2, cv = v + (down - up) / 2;
  const int reach = static_cast<int>(std::ceil(config.max_radius_ratio * radius_px));
  int radii[4] = {runToTurf(pixels, cu, cv, -1, 0, reach, classes),
                  runToTurf(pixels, cu, cv, 1, 0, reach, classes),
                  runToTurf(pixels, cu, cv, 0, -1, reach, classes),
                  runToTurf(pixels, cu, cv, 0, 1, reach, classes)};
  const auto [lo, hi] = std::minmax_element(radii, radii + 4);
  if (*lo < config.min_radius_ratio * radius_px || *hi > config.max_roundness * *lo) return false;
  const double r = 0.25 * (radii[0] + radii[1] + radii[2] + radii[3]);
  // Inside: patches among the samples; around: turf.
  constexpr int kSamples = 16;
  int inside = 0, patches = 0, around = 0, turf = 0;
  for (int k = 0; k < kSamples; ++k) {
    const double a = 2.0 * M_PI * k / kSamples, c = std::cos(a), s = std::sin(a);
    for (const double ring : {0.35, 0.7}) {
      const int x = cu + static_cast<int>(std::lround(ring * r * c));
      const int y = cv + static_cast<int>(std::lround(ring * r * s));
      if (x < 0 || y < 0 || x >= pixels.cols() || y >= pixels.rows()) continue;
      ++inside;
      patches += isPatch(pixels.at(x, y), classes);
    }
    const int x = cu + static_cast<int>(std::lround(config.ring_ratio * r * c));
    const int y = cv + static_cast<int>(std::lround(config.ring_ratio * r * s));
    if (x < 0 || y < 0 || x >= pixels.cols() || y >= pixels.rows()) continue;
    ++around;
    turf += isTurf(pixels.at(x, y), classes);
  }
  return inside > 0 && around > 0 && patches >= config.min_patch_share * inside &&
         turf >= config.min_ring_turf_share * around;
}

}  // namespace houghloc
