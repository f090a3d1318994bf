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
template <typename Pixels>
int runToTurf(const Pixels& pixels, int u, int v, int du, int dv, int limit,
              const BallClasses& classes) {
  int turf = 0;  // turf pixels in a row
  for (int k = 1; k <= limit + kTurfRun - 1; ++k) {
    const int x = u + du * k, y = v + dv * k;
    if (x < 0 || y < 0 || x >= pixels.cols() || y >= pixels.rows()) return -1;
    turf = isTurf(pixels.at(x, y), classes) ? turf + 1 : 0;
    if (turf == kTurfRun) return k - kTurfRun + 1;
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
  // The chord along the row, then along the column: a line runs on past `limit` along one of
  // them, which ends the test there (each line spot pays that one walk).
  const int left = runToTurf(pixels, u, v, -1, 0, limit, classes);
  const int right = left < 0 ? -1 : runToTurf(pixels, u, v, 1, 0, limit, classes);
  const int up = right < 0 ? -1 : runToTurf(pixels, u, v, 0, -1, limit, classes);
  const int down = up < 0 ? -1 : runToTurf(pixels, u, v, 0, 1, limit, classes);
  if (down < 0) return false;
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
