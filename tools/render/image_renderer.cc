#include "tools/render/image_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace houghloc {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

/// Unit directions of a truncated icosahedron's 12 pentagons (the icosahedron's vertices).
const std::vector<Eigen::Vector3d>& pentagonDirections() {
  static const std::vector<Eigen::Vector3d> dirs = [] {
    const double phi = 0.5 * (1.0 + std::sqrt(5.0));
    std::vector<Eigen::Vector3d> d;
    for (double a : {-1.0, 1.0}) {
      for (double b : {-phi, phi}) {
        d.push_back(Eigen::Vector3d(0, a, b).normalized());
        d.push_back(Eigen::Vector3d(a, b, 0).normalized());
        d.push_back(Eigen::Vector3d(b, 0, a).normalized());
      }
    }
    return d;
  }();
  return dirs;
}

/// A primitive's bounding sphere as seen from the camera, for tile culling.
struct Bound {
  Eigen::Vector3f dir_camera;        ///< unit, camera frame
  float cos_r = 1.0f, sin_r = 0.0f;  ///< angular radius
  bool everywhere = false;           ///< the camera is inside the bound
};

}  // namespace

ImageRenderer::ImageRenderer(const RayTable& rays, const GroundShader& ground,
                             const RoomShader& room, const RoomBox& box)
    : rays_(rays), ground_(ground), room_(room), box_(box) {}

float ImageRenderer::netAlpha(const Hit& hit, float footprint) const {
  constexpr float kSpacing = 0.1f, kThread = 0.008f;
  auto thread = [&](double coord) {
    const float f = static_cast<float>(coord / kSpacing - std::floor(coord / kSpacing)) * kSpacing;
    const float dist = std::min(f, kSpacing - f);
    const float exact =
        std::clamp((0.5f * kThread - dist) / std::max(footprint, 1e-4f) + 0.5f, 0.0f, 1.0f);
    const float mix = std::clamp(footprint / kSpacing, 0.0f, 1.0f);
    return (1.0f - mix) * exact + mix * kThread / kSpacing;
  };
  const float a = thread(hit.uv.x()), b = thread(hit.uv.y());
  return 0.85f * (1.0f - (1.0f - a) * (1.0f - b));
}

Eigen::Vector3f ImageRenderer::shadeObject(const Primitive& p, const Hit& hit,
                                           const Eigen::Vector3d& at) const {
  Eigen::Vector3f colour = p.material.bgr;
  const Eigen::Vector3d local = p.pattern_rotation.transpose() * hit.normal;
  if (p.material.pattern == Pattern::kBall) {
    for (const Eigen::Vector3d& d : pentagonDirections()) {
      if (local.dot(d) > 0.94) colour = Eigen::Vector3f(35, 35, 35);
    }
  } else if (p.material.pattern == Pattern::kHead && local.x() > 0.45 &&
             std::abs(local.z()) < 0.3) {
    colour = Eigen::Vector3f(70, 70, 70);  // the face plate around the eyes
  }
  // Overhead light: diffuse plus ambient, dimmed by the hall lighting below the object.
  static const Eigen::Vector3d kLight = Eigen::Vector3d(0.3, 0.2, 1.0).normalized();
  const double diffuse = std::max(0.0, hit.normal.dot(kLight));
  const float shade = static_cast<float>(0.45 + 0.6 * diffuse);
  return colour * shade * ground_.light(at.head<2>().cast<float>());
}

void ImageRenderer::render(const FrameView& view, const SceneObjects& objects,
                           RenderBuffers& out) const {
  const int w = rays_.width, h = rays_.height;
  out.bgr.create(h, w);
  out.occluder_depth.create(h, w);
  const Eigen::Matrix3f r = view.field_R_camera.cast<float>();
  const Eigen::Vector3f o = view.origin.cast<float>();
  const auto& prims = objects.primitives;
  std::vector<Bound> bounds(prims.size());
  for (size_t i = 0; i < prims.size(); ++i) {
    const Eigen::Vector3d v = prims[i].boundCenter() - view.origin;
    const double dist = v.norm(), rad = prims[i].boundRadius();
    Bound& b = bounds[i];
    b.everywhere = dist <= rad * 1.01 + 1e-6;
    if (b.everywhere) continue;
    b.dir_camera = (view.field_R_camera.transpose() * (v / dist)).cast<float>();
    const double ang = std::asin(rad / dist);
    b.cos_r = static_cast<float>(std::cos(ang));
    b.sin_r = static_cast<float>(std::sin(ang));
  }
  std::vector<int> candidates;
  for (int ty = 0; ty < rays_.tiles_y; ++ty) {
    for (int tx = 0; tx < rays_.tiles_x; ++tx) {
      const int tile = ty * rays_.tiles_x + tx;
      candidates.clear();
      for (size_t i = 0; i < prims.size(); ++i) {
        const Bound& b = bounds[i];
        if (b.everywhere) {
          candidates.push_back(static_cast<int>(i));
          continue;
        }
        // Inside the cone widened by the bound's angular radius: cos(angle) >= cos(half + r).
        const float cos_sum = rays_.tile_cos[tile] * b.cos_r - rays_.tile_sin[tile] * b.sin_r;
        const bool wide = rays_.tile_sin[tile] * b.cos_r + rays_.tile_cos[tile] * b.sin_r < 0.0f;
        if (wide || b.dir_camera.dot(rays_.tile_axis[tile]) >= cos_sum) {
          candidates.push_back(static_cast<int>(i));
        }
      }
      const int r0 = ty * RayTable::kTile, c0 = tx * RayTable::kTile;
      const int r1 = std::min(h, r0 + RayTable::kTile), c1 = std::min(w, c0 + RayTable::kTile);
      for (int row = r0; row < r1; ++row) {
        cv::Vec3f* out_row = out.bgr.ptr<cv::Vec3f>(row);
        float* depth_row = out.occluder_depth.ptr<float>(row);
        for (int col = c0; col < c1; ++col) {
          const int idx = rays_.index(col, row);
          const Eigen::Vector3f& ray_cam = rays_.ray[idx];
          if (!std::isfinite(ray_cam.x())) {  // outside the lens' field of view
            out_row[col] = cv::Vec3f(0, 0, 0);
            depth_row[col] = kInf;
            continue;
          }
          const Eigen::Vector3f d = r * ray_cam;
          // Opaque objects first: most pixels of a tile with objects still see the floor.
          Hit best;
          const Primitive* hit_prim = nullptr;
          const Eigen::Vector3d od = view.origin, dd = d.cast<double>();
          for (int k : candidates) {
            if (prims[k].opaque && prims[k].intersect(od, dd, best)) hit_prim = &prims[k];
          }
          Eigen::Vector3f colour;
          float t_scene;
          if (hit_prim) {
            t_scene = static_cast<float>(best.t);
            colour = shadeObject(*hit_prim, best, od + best.t * dd);
          } else if (d.z() < -1e-6f) {
            const float s = -o.z() / d.z();
            const Eigen::Vector2f g(o.x() + s * d.x(), o.y() + s * d.y());
            if (box_.containsFloor(g.x(), g.y())) {
              const Eigen::Vector3f du = r * rays_.ray_du[idx], dv = r * rays_.ray_dv[idx];
              Footprint fp;
              fp.du = s * (du.head<2>() - d.head<2>() * (du.z() / d.z()));
              fp.dv = s * (dv.head<2>() - d.head<2>() * (dv.z() / d.z()));
              colour = ground_.shade(g, fp, d.z(), objects.shadows);
              t_scene = s;
            } else {
              colour = room_.shade(o, d, &t_scene);
            }
          } else {
            colour = room_.shade(o, d, &t_scene);
          }
          depth_row[col] = hit_prim ? t_scene : kInf;
          // See-through nets in front of whatever was hit.
          for (int k : candidates) {
            if (prims[k].opaque) continue;
            Hit net;
            net.t = t_scene;
            if (!prims[k].intersect(od, dd, net)) continue;
            const float footprint = static_cast<float>(net.t) * rays_.ray_du[idx].norm();
            const float alpha = netAlpha(net, footprint);
            colour = (1.0f - alpha) * colour + alpha * shadeObject(prims[k], net, od + net.t * dd);
          }
          out_row[col] = cv::Vec3f(colour.x(), colour.y(), colour.z());
        }
      }
    }
  }
}

}  // namespace houghloc
