#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tools/render/ground_shader.h"
#include "tools/render/noise_texture.h"
#include "tools/render/scenario.h"

namespace houghloc {

/// What a ray sees when it does not hit the floor inside the hall: walls with doors, windows,
/// white boards and banners, and a ceiling with lamps.
class RoomShader {
 public:
  RoomShader(const RoomBox& room, const SceneConfig& scene, std::uint32_t seed);

  /// Colour along the ray origin + t dir (dir unit) where it leaves the hall; *t_out = t.
  Eigen::Vector3f shade(const Eigen::Vector3f& origin, const Eigen::Vector3f& dir,
                        float* t_out) const;

 private:
  struct Decor {
    int wall = 0;          ///< 0: x = +half_x, 1: y = +half_y, 2: x = -half_x, 3: y = -half_y
    float s0 = 0, s1 = 0;  ///< along the wall (m)
    float z0 = 0, z1 = 0;  ///< height (m)
    Eigen::Vector3f bgr;
    float frame = 0.0f;  ///< dark frame width (white boards), m
  };
  /// shade() before SceneConfig::hall_brightness.
  Eigen::Vector3f unlit(const Eigen::Vector3f& origin, const Eigen::Vector3f& dir,
                        float* t_out) const;
  Eigen::Vector3f wall(int wall, float s, float z) const;
  Eigen::Vector3f ceiling(float x, float y) const;

  RoomBox room_;
  SceneConfig scene_;
  std::vector<Decor> decor_;
  NoiseTexture texture_;
};

}  // namespace houghloc
