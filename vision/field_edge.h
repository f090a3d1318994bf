#pragma once

#include <vector>

#include "field_models/ground_points.h"
#include "vision/camera_model.h"
#include "vision/field_boundary.h"
#include "vision/ground_projection.h"

namespace houghloc {

struct FieldEdgeSamplingConfig {
  int columns = 24;                   ///< image columns sampled across the width
  double row_sigma_px = 2.0;          ///< error of the boundary row (sampled every few rows, fitted
                                      ///< by a hull): gives each sample's range sigma
  double max_range_m = 30.0;          ///< farther edges lie within a few pixels of the horizon
  double min_rows_below_start = 3.0;  ///< a boundary this close to the first scanned row (the
                                      ///< horizon or the image top) may be green beyond the
                                      ///< view, not the carpet's end
};

/// GroundPoints::field_edge: where the boundary crosses sampled columns, projected to the ground
/// at any range up to max_range_m (the points' range limit does not apply: the edge's use is
/// its distance at long range), with the range error of a row_sigma_px error.
std::vector<FieldEdgePoint> fieldEdgePoints(const CameraModel& camera,
                                            const FieldBoundary& boundary,
                                            const std::vector<int>& start_rows, int camera_id,
                                            const FieldEdgeSamplingConfig& config);

}  // namespace houghloc
