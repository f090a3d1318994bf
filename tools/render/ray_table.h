#pragma once

#include <Eigen/Core>
#include <vector>

#include "vision/camera_model.h"

namespace houghloc {

/// Viewing rays of every rendered (sub)pixel in the camera body frame, computed once per
/// intrinsics through CameraModel::pixelRay (so the renderer and the camera model agree exactly)
/// and rotated into the field per frame. Also the rays' per-pixel derivatives (for the ground
/// footprint used in anti-aliasing) and one bounding cone per tile (for culling objects).
struct RayTable {
  int width = 0, height = 0;  ///< rendered size = image size * supersampling
  int supersampling = 1;
  std::vector<Eigen::Vector3f> ray;     ///< unit; NaN outside the lens model's field of view
  std::vector<Eigen::Vector3f> ray_du;  ///< d ray / d (rendered) column
  std::vector<Eigen::Vector3f> ray_dv;  ///< d ray / d (rendered) row

  static constexpr int kTile = 16;  ///< rendered pixels per tile side
  int tiles_x = 0, tiles_y = 0;
  std::vector<Eigen::Vector3f> tile_axis;  ///< unit cone axis (camera frame)
  std::vector<float> tile_cos, tile_sin;   ///< of the cone's half angle

  int index(int col, int row) const { return row * width + col; }
  /// Image coordinate (distorted, pixel centres at integers) of a rendered column or row.
  double imageCoord(int rendered) const { return (rendered + 0.5) / supersampling - 0.5; }
};

RayTable makeRayTable(const CameraIntrinsics& intrinsics, int supersampling);

}  // namespace houghloc
