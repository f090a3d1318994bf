#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_models/ground_points.h"
#include "field_models/pose3.h"
#include "vision/camera_model.h"
#include "vision/field_boundary.h"
#include "vision/line_spots.h"

namespace houghloc {

struct GroundProjectionConfig {
  double max_range_m = 5.0;          ///< points farther from the robot than this are dropped
  double min_depression_rad = 0.06;  ///< rays flatter than this below the horizon (grazing, a
                                     ///< pixel covers decimetres of ground) are dropped
  double thin_cell_m = 0.035;        ///< at most one point per ground cell of this size: evens
                                     ///< out the near field and merges both scan directions'
                                     ///< hits of the same line (well under 10 cm spacing)
  double weight_range_m = 4.0;       ///< weight = 1 / (1 + (range / this)^2): far points are
                                     ///< less accurate
  int region_columns = 16;           ///< image columns sampled for the visible-region polygon
  double min_boundary_gap_m = 0.45;  ///< spots nearer than this to the field boundary's ground
                                     ///< point in their column are dropped (boundary_gap.h): the
                                     ///< goal frame's back bar lies 0.2-0.4 m from the carpet's
                                     ///< end, the outer lines 0.7-1 m
  double min_boundary_gap_range_m = 1.2;  ///< ... when that boundary point is at least this far
                                          ///< (nearer: an object on the field, boundary_gap.h)
};

/// A spot's viewing ray in the camera body frame. Computed once (undistortion is the expensive
/// part); projecting it with any camera orientation is then a rotation and a plane intersection,
/// which the pitch/roll correction relies on.
struct SpotRay {
  Eigen::Vector3d ray_camera = Eigen::Vector3d::UnitX();
  Eigen::Vector2f pixel = Eigen::Vector2f::Zero();
  bool vertical_scan = false;
  float width_px = 0.f;  ///< the spot's LineSpot::width_px
};

std::vector<SpotRay> spotRays(const CameraModel& camera, const std::vector<LineSpot>& spots);

/// No range limit and no grazing-angle limit: for geometry on rays already accepted (segments,
/// arcs, the boundary), where only where they hit the ground matters.
GroundProjectionConfig unlimitedProjection();

/// Intersects camera-frame rays with the ground z = 0 for one camera pose. Holds the pose's
/// rotation (Pose3::rotation() costs six sin/cos), for loops over many rays.
class GroundProjector {
 public:
  explicit GroundProjector(const Pose3& robot_T_camera);

  /// The ground point (robot frame) the ray hits; none above the horizon, at grazing angles or
  /// beyond the range limit.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& ray_camera,
                                         const GroundProjectionConfig& config) const;

  /// d(ground point) / d(roll, pitch) of the pose (GroundPoint::tilt_jacobian) for a ray that
  /// hits the ground; zero for one that does not.
  Eigen::Matrix2d tiltJacobian(const Eigen::Vector3d& ray_camera) const;

 private:
  Eigen::Matrix3d robot_R_camera_;
  Eigen::Matrix3d d_rotation_d_roll_, d_rotation_d_pitch_;
  Eigen::Vector3d origin_;
};

/// GroundProjector(robot_T_camera).project(ray_camera, config), for a single ray.
std::optional<Eigen::Vector2d> rayToGround(const Eigen::Vector3d& ray_camera,
                                           const Pose3& robot_T_camera,
                                           const GroundProjectionConfig& config);

/// Ground point (robot frame) of an image pixel under the camera's pose; none as rayToGround.
std::optional<Eigen::Vector2d> pixelToGround(const CameraModel& camera, double u, double v,
                                             const GroundProjectionConfig& config);

struct ProjectionStats {
  int dropped_range = 0;  ///< beyond max_range_m, grazing or above the horizon
  int thinned = 0;        ///< removed by the ground-cell thinning
};

/// Projects the rays with robot_T_camera, drops far/grazing ones and thins near ones.
std::vector<GroundPoint> projectSpots(const std::vector<SpotRay>& rays, const Pose3& robot_T_camera,
                                      int camera_id, const GroundProjectionConfig& config,
                                      ProjectionStats* stats = nullptr);

/// The ground the camera saw: field boundary (or range limit) and bottom image border projected
/// to the ground, robot frame, counter-clockwise seen from above; empty without a boundary.
GroundPolygon visibleRegion(const CameraModel& camera, const FieldBoundary& boundary,
                            const GroundProjectionConfig& config);

}  // namespace houghloc
