#pragma once

#include <Eigen/Core>
#include <vector>

namespace houghloc {

/// Centre of the circle of the given radius that best fits the points (least squares of the
/// radial distances), by Gauss-Newton from the algebraic (Kasa) fit's centre; a fixed number of
/// steps, so the result is a smooth function of the points (the pose corrector differentiates
/// through it numerically). False when the points are degenerate (fewer than 3, collinear).
bool fitCircleFixedRadius(const std::vector<Eigen::Vector2d>& points, double radius_m,
                          Eigen::Vector2d* center);

}  // namespace houghloc
