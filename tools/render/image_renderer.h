#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "tools/render/ground_shader.h"
#include "tools/render/ray_table.h"
#include "tools/render/room_shader.h"
#include "tools/render/scene_objects.h"

namespace houghloc {

/// Where the camera is in the field for one frame.
struct FrameView {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< optical centre, field frame (m)
  Eigen::Matrix3d field_R_camera = Eigen::Matrix3d::Identity();  ///< camera body frame
};

/// One rendered frame at the ray table's resolution, before sensor effects.
struct RenderBuffers {
  cv::Mat3f bgr;             ///< scene brightness, 8-bit scale (may exceed 255)
  cv::Mat1f occluder_depth;  ///< distance (m) to the nearest opaque object; +inf where none
};

/// Ray caster: for every (sub)pixel the ray hits the floor (turf, lines, gym floor), the walls
/// or ceiling, or one of the objects (robots, ball, goals, people, own feet); nets are blended
/// on top. Objects are culled per 16x16 tile with the tile's bounding cone, which keeps the cost
/// close to that of the floor alone.
class ImageRenderer {
 public:
  ImageRenderer(const RayTable& rays, const GroundShader& ground, const RoomShader& room,
                const RoomBox& box);
  void render(const FrameView& view, const SceneObjects& objects, RenderBuffers& out) const;

 private:
  Eigen::Vector3f shadeObject(const Primitive& p, const Hit& hit, const Eigen::Vector3d& at) const;
  float netAlpha(const Hit& hit, float footprint_m) const;

  const RayTable& rays_;
  const GroundShader& ground_;
  const RoomShader& room_;
  RoomBox box_;
};

}  // namespace houghloc
