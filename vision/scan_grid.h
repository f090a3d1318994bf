#pragma once

#include <vector>

#include "vision/camera_model.h"
#include "vision/field_boundary.h"
#include "vision/line_width_model.h"

namespace houghloc {

struct ScanGridConfig {
  double target_spacing_m = 0.05;  ///< ground distance between neighbouring scanlines
  int min_row_step_px = 1;         ///< densest horizontal scanline spacing
  int min_column_step_px = 2;      ///< densest vertical scanline spacing
  int max_step_px = 32;            ///< sparsest spacing (near the robot)
  double max_range_m = 5.0;        ///< rows whose ground is farther than this are not scanned ...
  /// ... with the camera looking this much further down than its pose says (rad): a recorded
  /// pitch is often a few degrees short, and the pitch/roll correction and the rescans that find
  /// it run after the scan, so spots beyond the range at the recorded pose may end up within it
  /// (docs/vision.md "Scan range").
  double range_pitch_margin_rad = 0.0175;
  int margin_row_step_px = 4;  ///< rows in that margin's band are at least this far apart
};

/// Where to look: horizontal scanlines at rows spaced so neighbouring rows see ground about
/// target_spacing_m apart, and vertical scanlines in a hierarchy (every min step far away, every
/// second one closer, ...) so their ground spacing is about even too. Near the robot the image
/// is sparse-scanned, far away densely, never past the field boundary or the range limit.
struct ScanGrid {
  struct Column {
    int u = 0;
    int v_begin = 0;  ///< first row (field boundary, range limit)
    int v_end = 0;    ///< one past the last row
  };
  std::vector<int> rows;        ///< horizontal scanline rows, bottom to top
  std::vector<Column> columns;  ///< vertical scanlines, left to right
  int top_row = 0;              ///< nothing above this row is scanned (range limit)
};

ScanGrid makeScanGrid(const CameraModel& camera, const LineWidthModel& widths,
                      const FieldBoundary& boundary, const ScanGridConfig& config = {});

}  // namespace houghloc
