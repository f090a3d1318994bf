#pragma once

#include <vector>

#include "vision/camera_model.h"
#include "vision/field_boundary.h"
#include "vision/ground_projection.h"

namespace houghloc {

/// Drops spots whose ground point lies closer than min_gap_m to the ground point of the field
/// boundary in their column. Every field line has the border strip (0.7-1 m on the standard
/// fields) of turf beyond it, while the goal frame's bar lying on the ground at the back of the
/// goal (0.5-0.6 m behind the goal line) is within a few decimetres of the carpet's end; far
/// away it is as thin and as sharp as a line. Columns whose boundary is not a seen end of the
/// green (at the scan start row: the field reaches the image top or the horizon) keep all spots,
/// and so do columns whose boundary lies nearer than min_boundary_range_m: a boundary that near
/// is mostly an object standing on the field (a NAO's bottom camera, which sees 0.2-0.6 m ahead
/// while walking, has another robot's foot as its boundary and every spot within 0.45 m of it),
/// and the bar that near shows its round, soft edges (line_spots.h).
/// min_gap_m <= 0 keeps everything.
std::vector<SpotRay> dropSpotsNearBoundary(const std::vector<SpotRay>& rays,
                                           const CameraModel& camera, const FieldBoundary& boundary,
                                           const std::vector<int>& start_rows, double min_gap_m,
                                           double min_boundary_range_m, int* dropped = nullptr);

}  // namespace houghloc
