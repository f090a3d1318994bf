#include "vision/ground_projection.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "vision/cell_key.h"

namespace houghloc {

std::vector<SpotRay> spotRays(const CameraModel& camera, const std::vector<LineSpot>& spots) {
  const Eigen::Matrix3d camera_R_robot = camera.pose().rotation().transpose();
  std::vector<SpotRay> rays;
  rays.reserve(spots.size());
  for (const LineSpot& spot : spots) {
    const Eigen::Vector3d ray_robot = camera.pixelRay(spot.pixel.x(), spot.pixel.y());
    if (!ray_robot.allFinite()) continue;
    const Eigen::Vector3d ray_camera = camera_R_robot * ray_robot;
    rays.push_back({ray_camera, spot.pixel, spot.vertical_scan, spot.width_px});
  }
  return rays;
}

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

}  // namespace

GroundProjector::GroundProjector(const Pose3& robot_T_camera)
    : robot_R_camera_(robot_T_camera.rotation()), origin_(robot_T_camera.translation()) {
  // R = Rz(yaw) Ry(pitch) Rx(roll) (Pose3); d/da of a rotation by a about axis e is R(a) [e]x.
  const Eigen::Matrix3d yaw(Eigen::AngleAxisd(robot_T_camera.yaw, Eigen::Vector3d::UnitZ()));
  const Eigen::Matrix3d pitch(Eigen::AngleAxisd(robot_T_camera.pitch, Eigen::Vector3d::UnitY()));
  const Eigen::Matrix3d roll(Eigen::AngleAxisd(robot_T_camera.roll, Eigen::Vector3d::UnitX()));
  d_rotation_d_roll_ = robot_R_camera_ * skew(Eigen::Vector3d::UnitX());
  d_rotation_d_pitch_ = yaw * pitch * skew(Eigen::Vector3d::UnitY()) * roll;
}

Eigen::Matrix2d GroundProjector::tiltJacobian(const Eigen::Vector3d& ray_camera) const {
  const Eigen::Vector3d ray = robot_R_camera_ * ray_camera;
  Eigen::Matrix2d jacobian = Eigen::Matrix2d::Zero();
  if (!(ray.z() < 0.0) || origin_.z() <= 0.0) return jacobian;
  // p = o + s ray with s = -o_z / ray_z: dp = s d(ray) + ds ray, ds = o_z d(ray_z) / ray_z^2.
  const double s = -origin_.z() / ray.z();
  const Eigen::Vector3d d_ray[2] = {d_rotation_d_roll_ * ray_camera,
                                    d_rotation_d_pitch_ * ray_camera};
  for (int k = 0; k < 2; ++k) {
    const double ds = origin_.z() * d_ray[k].z() / (ray.z() * ray.z());
    jacobian.col(k) = s * d_ray[k].head<2>() + ds * ray.head<2>();
  }
  return jacobian;
}

GroundProjectionConfig unlimitedProjection() {
  GroundProjectionConfig config;
  config.max_range_m = 1e9;
  config.min_depression_rad = 0.0;
  return config;
}

std::optional<Eigen::Vector2d> GroundProjector::project(
    const Eigen::Vector3d& ray_camera, const GroundProjectionConfig& config) const {
  const Eigen::Vector3d ray = robot_R_camera_ * ray_camera;
  const double norm = ray.norm();
  if (origin_.z() <= 0.0 || !(norm > 0.0)) return std::nullopt;
  if (-ray.z() / norm < std::sin(config.min_depression_rad)) return std::nullopt;
  const double s = origin_.z() / -ray.z();
  const Eigen::Vector2d p(origin_.x() + s * ray.x(), origin_.y() + s * ray.y());
  if (p.norm() > config.max_range_m) return std::nullopt;
  return p;
}

std::optional<Eigen::Vector2d> rayToGround(const Eigen::Vector3d& ray_camera,
                                           const Pose3& robot_T_camera,
                                           const GroundProjectionConfig& config) {
  return GroundProjector(robot_T_camera).project(ray_camera, config);
}

std::vector<GroundPoint> projectSpots(const std::vector<SpotRay>& rays, const Pose3& robot_T_camera,
                                      int camera_id, const GroundProjectionConfig& config,
                                      ProjectionStats* stats) {
  std::vector<GroundPoint> points;
  points.reserve(rays.size());
  std::unordered_set<std::int64_t> cells;
  const double cell = std::max(1e-3, config.thin_cell_m);
  const GroundProjector projector(robot_T_camera);
  for (const SpotRay& ray : rays) {
    const auto p = projector.project(ray.ray_camera, config);
    if (!p) {
      if (stats) ++stats->dropped_range;
      continue;
    }
    const std::int64_t cx = static_cast<std::int64_t>(std::floor(p->x() / cell));
    const std::int64_t cy = static_cast<std::int64_t>(std::floor(p->y() / cell));
    if (!cells.insert(cellKey(cx, cy)).second) {
      if (stats) ++stats->thinned;
      continue;
    }
    GroundPoint point;
    point.p_robot = *p;
    const double r = p->norm() / config.weight_range_m;
    point.weight = 1.0 / (1.0 + r * r);
    point.pixel = ray.pixel;
    point.camera_id = camera_id;
    point.tilt_jacobian = projector.tiltJacobian(ray.ray_camera);
    points.push_back(point);
  }
  return points;
}

std::optional<Eigen::Vector2d> pixelToGround(const CameraModel& camera, double u, double v,
                                             const GroundProjectionConfig& config) {
  const Eigen::Vector3d ray = camera.pixelRay(u, v);
  if (!ray.allFinite()) return std::nullopt;
  const Pose3& pose = camera.pose();
  return rayToGround(pose.rotation().transpose() * ray, pose, config);
}

namespace {

/// Ground point of a pixel, or where its ray's azimuth meets the range limit when the pixel
/// sees farther (or above the horizon).
std::optional<Eigen::Vector2d> groundOrLimit(const CameraModel& camera, double u, double v,
                                             const GroundProjectionConfig& config) {
  if (const auto p = pixelToGround(camera, u, v, config)) return p;
  const Eigen::Vector3d ray = camera.pixelRay(u, v);
  const Eigen::Vector2d direction(ray.x(), ray.y());
  if (!direction.allFinite() || direction.norm() < 1e-9) return std::nullopt;
  return config.max_range_m * direction.normalized();
}

}  // namespace

GroundPolygon visibleRegion(const CameraModel& camera, const FieldBoundary& boundary,
                            const GroundProjectionConfig& config) {
  GroundPolygon polygon;
  if (!boundary.found) return polygon;
  const int n = std::max(2, config.region_columns);
  const double bottom = camera.height() - 1.0;
  std::vector<Eigen::Vector2d> far_edge, near_edge;
  for (int i = 0; i <= n; ++i) {
    const double u = (camera.width() - 1.0) * i / n;
    const double top = boundary.rowAt(static_cast<int>(u));
    if (top >= bottom) continue;
    const auto far_point = groundOrLimit(camera, u, top, config);
    const auto near_point = groundOrLimit(camera, u, bottom, config);
    if (!far_point || !near_point) continue;
    far_edge.push_back(*far_point);
    near_edge.push_back(*near_point);
  }
  if (far_edge.size() < 2) return polygon;
  // Image left to right is robot-frame right to left (counter-clockwise on the far edge) when
  // the camera looks forward; the orientation test below fixes the order for any yaw.
  polygon = near_edge;
  polygon.insert(polygon.end(), far_edge.rbegin(), far_edge.rend());
  double area2 = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    area2 += a.x() * b.y() - a.y() * b.x();
  }
  if (area2 < 0.0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

}  // namespace houghloc
