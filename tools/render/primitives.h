#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

namespace houghloc {

/// How a primitive's surface looks. Colours are 8-bit BGR scaled to float (0..255).
enum class Pattern { kPlain, kBall, kNet, kHead, kSkin };

struct Material {
  Eigen::Vector3f bgr = Eigen::Vector3f(200.0f, 200.0f, 200.0f);
  Pattern pattern = Pattern::kPlain;
};

/// A ray hit: distance along the unit ray (m) and the outward surface normal.
struct Hit {
  double t = std::numeric_limits<double>::infinity();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();  ///< panels: position on the panel (m)
};

/// A simple 3-D shape in the field frame: robots, ball, goals, people and the robot's own feet
/// are made of these. Opaque ones hide the ground (and are recorded in the occlusion depth);
/// nets are see-through.
struct Primitive {
  enum class Kind { kSphere, kCapsule, kBox, kPanel };
  Kind kind = Kind::kSphere;
  Eigen::Vector3d a = Eigen::Vector3d::Zero();  ///< sphere/box centre, capsule end, panel corner
  Eigen::Vector3d b = Eigen::Vector3d::Zero();  ///< capsule end, box half extents, panel edge 1
  Eigen::Vector3d c = Eigen::Vector3d::Zero();  ///< panel edge 2
  double radius = 0.0;                          ///< sphere, capsule
  double yaw = 0.0;                             ///< box rotation about z (rad)
  Eigen::Matrix3d pattern_rotation = Eigen::Matrix3d::Identity();  ///< ball: its spin
  Material material;
  bool opaque = true;

  /// Bounding sphere, for culling against image tiles.
  Eigen::Vector3d boundCenter() const;
  double boundRadius() const;
  /// Nearest hit with t > 0 of the ray origin + t * dir (dir unit), if any.
  bool intersect(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, Hit& hit) const;
};

Primitive makeSphere(const Eigen::Vector3d& center, double radius, const Material& m);
Primitive makeCapsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius,
                      const Material& m);
Primitive makeBox(const Eigen::Vector3d& center, const Eigen::Vector3d& half_extents, double yaw,
                  const Material& m);
/// A see-through net panel: corner + edge1 + edge2 (a parallelogram).
Primitive makeNetPanel(const Eigen::Vector3d& corner, const Eigen::Vector3d& edge1,
                       const Eigen::Vector3d& edge2, const Material& m);

}  // namespace houghloc
