#include "tools/render/ray_table.h"

#include <algorithm>
#include <cmath>

namespace houghloc {
namespace {

bool finite(const Eigen::Vector3f& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

}  // namespace

RayTable makeRayTable(const CameraIntrinsics& intrinsics, int supersampling) {
  RayTable t;
  t.supersampling = supersampling;
  t.width = intrinsics.image_width * supersampling;
  t.height = intrinsics.image_height * supersampling;
  // With the identity pose the robot frame is the camera body frame.
  const CameraModel camera(intrinsics, Pose3{});
  const size_t n = static_cast<size_t>(t.width) * t.height;
  t.ray.resize(n);
  for (int r = 0; r < t.height; ++r) {
    for (int c = 0; c < t.width; ++c) {
      t.ray[t.index(c, r)] = camera.pixelRay(t.imageCoord(c), t.imageCoord(r)).cast<float>();
    }
  }
  // Central differences (one-sided at the border and next to invalid rays).
  t.ray_du.assign(n, Eigen::Vector3f::Zero());
  t.ray_dv.assign(n, Eigen::Vector3f::Zero());
  auto diff = [&](int c0, int r0, int c1, int r1, float span) -> Eigen::Vector3f {
    const Eigen::Vector3f& a = t.ray[t.index(c0, r0)];
    const Eigen::Vector3f& b = t.ray[t.index(c1, r1)];
    return (finite(a) && finite(b)) ? Eigen::Vector3f((b - a) / span) : Eigen::Vector3f::Zero();
  };
  for (int r = 0; r < t.height; ++r) {
    for (int c = 0; c < t.width; ++c) {
      const int cl = std::max(0, c - 1), cr = std::min(t.width - 1, c + 1);
      const int ru = std::max(0, r - 1), rd = std::min(t.height - 1, r + 1);
      Eigen::Vector3f du = diff(cl, r, cr, r, static_cast<float>(cr - cl));
      if (du.isZero()) du = diff(c, r, cr, r, static_cast<float>(std::max(1, cr - c)));
      if (du.isZero()) du = diff(cl, r, c, r, static_cast<float>(std::max(1, c - cl)));
      Eigen::Vector3f dv = diff(c, ru, c, rd, static_cast<float>(rd - ru));
      if (dv.isZero()) dv = diff(c, r, c, rd, static_cast<float>(std::max(1, rd - r)));
      if (dv.isZero()) dv = diff(c, ru, c, r, static_cast<float>(std::max(1, r - ru)));
      t.ray_du[t.index(c, r)] = du;
      t.ray_dv[t.index(c, r)] = dv;
    }
  }
  // Tile cones: axis through the mean ray, half angle reaching every border ray of the tile.
  t.tiles_x = (t.width + RayTable::kTile - 1) / RayTable::kTile;
  t.tiles_y = (t.height + RayTable::kTile - 1) / RayTable::kTile;
  for (int ty = 0; ty < t.tiles_y; ++ty) {
    for (int tx = 0; tx < t.tiles_x; ++tx) {
      const int c0 = tx * RayTable::kTile, r0 = ty * RayTable::kTile;
      const int c1 = std::min(t.width, c0 + RayTable::kTile) - 1;
      const int r1 = std::min(t.height, r0 + RayTable::kTile) - 1;
      Eigen::Vector3f axis = Eigen::Vector3f::Zero();
      for (int r = r0; r <= r1; ++r) {
        for (int c = c0; c <= c1; ++c) {
          if (finite(t.ray[t.index(c, r)])) axis += t.ray[t.index(c, r)];
        }
      }
      float cos_half = 1.0f;
      if (axis.norm() > 0.0f) {
        axis.normalize();
        for (int r = r0; r <= r1; ++r) {
          for (int c = c0; c <= c1; ++c) {
            const Eigen::Vector3f& ray = t.ray[t.index(c, r)];
            if (finite(ray)) cos_half = std::min(cos_half, axis.dot(ray));
          }
        }
      } else {
        axis = Eigen::Vector3f::UnitX();
        cos_half = -1.0f;  // no valid ray: the cone is everything (never used)
      }
      // Half a pixel of margin for the rays between samples.
      const float half = std::acos(std::clamp(cos_half, -1.0f, 1.0f)) + 0.002f;
      t.tile_axis.push_back(axis);
      t.tile_cos.push_back(std::cos(std::min(half, 3.14159f)));
      t.tile_sin.push_back(std::sin(std::min(half, 3.14159f)));
    }
  }
  return t;
}

}  // namespace houghloc
