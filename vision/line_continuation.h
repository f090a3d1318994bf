#pragma once

#include <algorithm>
#include <cmath>

#include "vision/field_color.h"
#include "vision/line_spots.h"  // LineSpot, LineContinuationConfig
#include "vision/pixel_access.h"
#include "vision/scanline.h"

namespace houghloc {

/// What bounds a run beside a spot: `dark_luma` (darker pixels are no turf: a ball's black
/// patch, a robot's joint) and the turf colour.
struct RunBounds {
  const FieldColor& color;
  int dark_luma;
};

/// Whether, walking from pixel `from` in direction dir for up to `count` px, turf or the end of
/// the stretch comes before anything dark.
template <typename Run>
bool noDarkBeforeTurf(const Scanline<Run>& line, int from, int dir, int count,
                      const RunBounds& bounds) {
  for (int k = 0; k < count; ++k) {
    const int i = from + dir * k;
    if (i < 0 || i >= line.n) return true;
    if (line.luma(i) < bounds.dark_luma) return false;
    if (bounds.color.isField(line.at(i))) return true;
  }
  return true;
}

/// The run of a scanline beside a spot: the brightest pixel near where the line would cross it,
/// and its half-maximum width. Found only when it rises `min_rise` above the darker ends of the
/// stretch on both sides, and when on neither side anything dark comes before the turf within a
/// quarter of its width (at least 2 px): a line's run beside it is bounded by turf, while the
/// white between a ball's black patches is about as wide as the rim chord it continues.
template <typename Run>
bool runBeside(const Scanline<Run>& line, int centre, int reach, int min_rise,
               const RunBounds& bounds, float* width) {
  int peak = std::clamp(centre, 0, line.n - 1);
  for (int i = std::max(0, centre - reach); i <= std::min(line.n - 1, centre + reach); ++i) {
    if (line.luma(i) > line.luma(peak)) peak = i;
  }
  int before = line.luma(peak), after = line.luma(peak);
  for (int i = 0; i < peak; ++i) before = std::min(before, line.luma(i));
  for (int i = peak + 1; i < line.n; ++i) after = std::min(after, line.luma(i));
  if (line.luma(peak) - std::max(before, after) < min_rise) return false;
  const float level = 0.5f * (line.luma(peak) + 0.5f * (before + after));
  const float left = levelCrossing(line, peak, -1, level);
  const float right = levelCrossing(line, peak, +1, level);
  const int margin = std::max(2, static_cast<int>(0.25f * (right - left)));
  if (!noDarkBeforeTurf(line, static_cast<int>(left), -1, margin, bounds) ||
      !noDarkBeforeTurf(line, static_cast<int>(std::ceil(right)), +1, margin, bounds)) {
    return false;
  }
  *width = right - left;
  return true;
}

/// Whether the bright run of `spot` goes on, with about its width, in at least one of the two
/// parallel scanlines a little to either side. A field line does (its end, a junction or the
/// image border may stop it on one side); a compact white blob of about a line's width, the
/// rim of a ball or a robot's foot seen close by the bottom camera, narrows to nothing on its
/// outer side and widens on its inner side. A spot with no scanline beside it in the image
/// passes.
template <typename Pixels>
bool continuesBeside(const Pixels& pixels, const LineSpot& spot, int min_rise,
                     const RunBounds& bounds, const LineContinuationConfig& config,
                     RunBuffer* buffer) {
  if (!config.enabled) return true;
  const float width = spot.width_px;
  const int offset = std::max(config.min_offset_px,
                              static_cast<int>(std::lround(config.offset_width_share * width)));
  // A line crossing the scanlines at up to ~55 deg from square (steeper lines are too wide
  // along these scanlines and are found by the other direction) shifts by up to 1.5 x offset.
  const int reach = static_cast<int>(std::ceil(0.5f * width)) + (3 * offset) / 2 + 1;
  const int half = static_cast<int>(std::ceil(width)) + 2 * offset + 2;
  const int u = static_cast<int>(std::lround(spot.pixel.x()));
  const int v = static_cast<int>(std::lround(spot.pixel.y()));
  bool beside_in_image = false;
  for (const int side : {-1, +1}) {
    float beside = 0.f;
    if (spot.vertical_scan) {
      const int column = u + side * offset;
      const int top = std::max(0, v - half), bottom = std::min(pixels.rows(), v + half + 1);
      if (column < 0 || column >= pixels.cols() || bottom - top < 4) continue;
      beside_in_image = true;
      const auto line = scanline(pixels.columnRun(column, top, bottom - top, buffer), bottom - top,
                                 column, top, 0, 1);
      if (!runBeside(line, v - top, reach, min_rise, bounds, &beside)) continue;
    } else {
      const int row = v + side * offset;
      const int left = std::max(0, u - half), right = std::min(pixels.cols(), u + half + 1);
      if (row < 0 || row >= pixels.rows() || right - left < 4) continue;
      beside_in_image = true;
      const auto line =
          scanline(pixels.rowRun(left, row, right - left, buffer), right - left, left, row, 1, 0);
      if (!runBeside(line, u - left, reach, min_rise, bounds, &beside)) continue;
    }
    const float ratio = static_cast<float>(config.max_width_ratio);
    const float tolerance = static_cast<float>(config.width_tolerance_px);
    if (beside <= ratio * width + tolerance && beside >= width / ratio - tolerance) return true;
  }
  return !beside_in_image;
}

}  // namespace houghloc
