#include "tools/render/room_shader.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace houghloc {
namespace {

const Eigen::Vector3f kDado(125.0f, 110.0f, 100.0f);  ///< lower wall paint
const Eigen::Vector3f kWall(200.0f, 208.0f, 212.0f);  ///< upper wall paint
const Eigen::Vector3f kCeiling(150.0f, 152.0f, 155.0f);
const Eigen::Vector3f kLamp(300.0f, 300.0f, 290.0f);  ///< over-exposed
const Eigen::Vector3f kPlain(90.0f, 90.0f, 90.0f);    ///< walls switched off

}  // namespace

RoomShader::RoomShader(const RoomBox& room, const SceneConfig& scene, std::uint32_t seed)
    : room_(room), scene_(scene), texture_(128, 0.05, 1.5, seed * 11u + 1u) {
  if (!scene.walls) return;
  std::mt19937 rng(seed * 11u + 2u);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const std::vector<Eigen::Vector3f> banners = {
      {40, 40, 190}, {170, 90, 20}, {30, 160, 220}, {60, 140, 40}, {150, 60, 140}};
  for (int w = 0; w < 4; ++w) {
    const float half = static_cast<float>((w % 2 == 0) ? room.half_y : room.half_x);
    // Windows high up in a row; doors, white boards and banners at random places.
    for (float s = -half + 1.0f + 2.0f * u(rng); s < half - 2.0f; s += 3.0f + 1.0f * u(rng)) {
      decor_.push_back({w, s, s + 2.0f, 3.4f, 5.0f, Eigen::Vector3f(290, 285, 270), 0.0f});
    }
    for (int k = 0; k < 2; ++k) {
      const float s = -half + 1.0f + (2.0f * half - 3.0f) * u(rng);
      decor_.push_back({w, s, s + 1.0f, 0.0f, 2.1f, Eigen::Vector3f(50, 70, 95), 0.0f});
    }
    for (int k = 0; k < 2; ++k) {
      const float s = -half + 1.0f + (2.0f * half - 3.0f) * u(rng);
      decor_.push_back({w, s, s + 1.8f, 0.9f, 2.1f, Eigen::Vector3f(235, 238, 238), 0.04f});
    }
    const float s = -half + 1.0f + (2.0f * half - 5.0f) * u(rng);
    decor_.push_back(
        {w, s, s + 4.0f, 2.3f, 3.1f, banners[static_cast<size_t>(u(rng) * 4.99f)], 0.0f});
  }
}

Eigen::Vector3f RoomShader::wall(int w, float s, float z) const {
  Eigen::Vector3f colour = z < 1.1f ? kDado : kWall;
  for (const Decor& d : decor_) {
    if (d.wall != w || s < d.s0 || s > d.s1 || z < d.z0 || z > d.z1) continue;
    const bool on_frame = d.frame > 0.0f && (s < d.s0 + d.frame || s > d.s1 - d.frame ||
                                             z < d.z0 + d.frame || z > d.z1 - d.frame);
    colour = on_frame ? Eigen::Vector3f(60, 60, 60) : d.bgr;
  }
  return colour * (1.0f + 0.025f * texture_.sample(s, z, 0.05f));
}

Eigen::Vector3f RoomShader::ceiling(float x, float y) const {
  // Rows of lamps between dark beams.
  const float fx = x / 3.0f - std::floor(x / 3.0f), fy = y / 2.0f - std::floor(y / 2.0f);
  if (std::abs(fx - 0.5f) < 0.2f && std::abs(fy - 0.5f) < 0.08f) return kLamp;
  if (std::abs(fy - 0.0f) < 0.03f) return kCeiling * 0.6f;
  return kCeiling * (1.0f + 0.05f * texture_.sample(x, y, 0.0f));
}

Eigen::Vector3f RoomShader::shade(const Eigen::Vector3f& o, const Eigen::Vector3f& d,
                                  float* t_out) const {
  return static_cast<float>(scene_.hall_brightness) * unlit(o, d, t_out);
}

Eigen::Vector3f RoomShader::unlit(const Eigen::Vector3f& o, const Eigen::Vector3f& d,
                                  float* t_out) const {
  // The ray starts inside the box: the exit is the nearest positive plane crossing.
  float t = 1e6f;
  int hit = -1;
  auto consider = [&](float tc, int which) {
    if (tc > 0.0f && tc < t) {
      t = tc;
      hit = which;
    }
  };
  const float hx = static_cast<float>(room_.half_x), hy = static_cast<float>(room_.half_y);
  if (d.x() > 1e-9f) consider((hx - o.x()) / d.x(), 0);
  if (d.x() < -1e-9f) consider((-hx - o.x()) / d.x(), 2);
  if (d.y() > 1e-9f) consider((hy - o.y()) / d.y(), 1);
  if (d.y() < -1e-9f) consider((-hy - o.y()) / d.y(), 3);
  if (d.z() > 1e-9f) consider((static_cast<float>(room_.height) - o.z()) / d.z(), 4);
  *t_out = t;
  if (!scene_.walls) return kPlain;
  const Eigen::Vector3f p = o + t * d;
  switch (hit) {
    case 0:
      return wall(0, p.y(), p.z());
    case 1:
      return wall(1, -p.x(), p.z());
    case 2:
      return wall(2, -p.y(), p.z());
    case 3:
      return wall(3, p.x(), p.z());
    case 4:
      return ceiling(p.x(), p.y());
    default:
      return kPlain;
  }
}

}  // namespace houghloc
