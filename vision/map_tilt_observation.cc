#include "vision/map_tilt_observation.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "field_models/field_distance.h"
#include "vision/ground_projection.h"

namespace houghloc {

MapTiltObservation::MapTiltObservation(std::vector<Eigen::Vector3d> rays_camera,
                                       std::vector<double> sigma_m,
                                       const Pose2& field_T_robot_guess)
    : rays_(std::move(rays_camera)),
      sigma_(std::move(sigma_m)),
      guess_(field_T_robot_guess),
      fitted_(field_T_robot_guess),
      matches_(rays_.size()) {}

std::vector<Eigen::Vector2d> MapTiltObservation::project(const Pose3& robot_T_camera) const {
  const GroundProjectionConfig unlimited = unlimitedProjection();
  std::vector<Eigen::Vector2d> points;
  points.reserve(rays_.size());
  const GroundProjector projector(robot_T_camera);
  for (const Eigen::Vector3d& ray : rays_) {
    const auto p = projector.project(ray, unlimited);
    points.push_back(p ? *p : Eigen::Vector2d::Constant(std::nan("")));
  }
  return points;
}

Pose2 MapTiltObservation::fitPose(const std::vector<Eigen::Vector2d>& points, const Pose2& start,
                                  int iterations) const {
  Pose2 pose = start;
  for (int it = 0; it < iterations; ++it) {
    const Eigen::Matrix2d rotation = pose.rotation();
    const Eigen::Vector2d translation = pose.translation();
    Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < points.size(); ++i) {
      const Match& m = matches_[i];
      if (!m.valid || !points[i].allFinite()) continue;
      const Eigen::Vector2d rotated = rotation * points[i];
      const double distance = m.normal.dot(rotated + translation - m.point);
      const Eigen::Vector3d jacobian(m.normal.x(), m.normal.y(),
                                     m.normal.dot(Eigen::Vector2d(-rotated.y(), rotated.x())));
      const double w = 1.0 / (sigma_[i] * sigma_[i]);
      normal_matrix += w * jacobian * jacobian.transpose();
      gradient += w * jacobian * distance;
    }
    // Lines of one direction leave the shift along them open: a little damping keeps it put.
    normal_matrix.diagonal().array() += 1e-9 * normal_matrix.trace() + 1e-12;
    const Eigen::Vector3d step = -normal_matrix.ldlt().solve(gradient);
    if (!step.allFinite()) break;
    pose = Pose2(pose.x + step(0), pose.y + step(1), pose.theta + step(2));
  }
  return pose;
}

int MapTiltObservation::match(const FieldModel& field, const std::vector<Eigen::Vector2d>& points,
                              const Pose2& field_T_robot, double radius_m, double max_range_m) {
  inliers_ = 0;
  int tried = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    Match& m = matches_[i];
    m.valid = false;
    if (!points[i].allFinite() || !(points[i].norm() <= max_range_m)) continue;
    ++tried;
    const NearestFeature nearest = nearestFeature(field, field_T_robot.transform(points[i]));
    // The true distance gates (a point beyond a line's end is no point of it); the fit uses the
    // distance along the normal, smooth in the pose.
    if (nearest.feature.index < 0 || !(nearest.distance_m <= radius_m)) continue;
    const int k = nearest.feature.index;
    if (nearest.feature.kind == FeatureKind::kSegment) {
      const Eigen::Vector2d d = field.segments[static_cast<size_t>(k)].direction();
      m.normal = Eigen::Vector2d(-d.y(), d.x());
    } else if (nearest.feature.kind == FeatureKind::kArc) {
      m.normal = nearest.closest_point - field.arcs[static_cast<size_t>(k)].center;
    } else {
      continue;
    }
    if (!(m.normal.norm() > 1e-9)) continue;
    m.normal.normalize();
    m.point = nearest.closest_point;
    m.feature = nearest.feature;
    m.valid = true;
    ++inliers_;
  }
  return tried;
}

int MapTiltObservation::associate(const FieldModel& field, const Pose3& robot_T_camera,
                                  const MapTiltConfig& config, double max_range_m) {
  const std::vector<Eigen::Vector2d> points = project(robot_T_camera);
  match(field, points, guess_, config.search_radius_m, max_range_m);
  fitted_ = fitPose(points, guess_, config.pose_fit_iterations);
  const int tried = match(field, points, fitted_, config.gate_m, max_range_m);
  fitted_ = fitPose(points, fitted_, config.pose_fit_iterations);
  const Pose2 moved = guess_.inverse() * fitted_;
  const bool near_guess = moved.translation().norm() <= config.max_pose_shift_m &&
                          std::abs(moved.theta) <= config.max_pose_turn_rad;
  if (!near_guess || inliers_ < config.min_inliers || !showsTilt(points, config) ||
      inliers_ < config.min_inlier_share * static_cast<double>(tried)) {
    for (Match& m : matches_) m.valid = false;
    inliers_ = 0;
  }
  return inliers_;
}

bool MapTiltObservation::showsTilt(const std::vector<Eigen::Vector2d>& points,
                                   const MapTiltConfig& config) const {
  std::map<std::pair<int, int>, int> per_feature;  // (kind, index) -> matches
  Eigen::AlignedBox2d extent;
  for (size_t i = 0; i < matches_.size(); ++i) {
    const Match& m = matches_[i];
    if (!m.valid) continue;
    ++per_feature[{static_cast<int>(m.feature.kind), m.feature.index}];
    extent.extend(points[i]);
  }
  if (extent.isEmpty() || !(extent.diagonal().norm() >= config.min_spread_m)) return false;
  int lines = 0;
  for (const auto& [feature, count] : per_feature) {
    if (count < config.min_points_per_line) continue;
    if (feature.first == static_cast<int>(FeatureKind::kArc)) return true;
    ++lines;
  }
  return lines >= 2;
}

void MapTiltObservation::residuals(const Pose3& robot_T_camera, const MapTiltConfig& config,
                                   std::vector<double>* out, std::vector<double>* gates) const {
  const std::vector<Eigen::Vector2d> points = project(robot_T_camera);
  const Pose2 pose = fitPose(points, fitted_, config.pose_fit_iterations);
  const Eigen::Matrix2d rotation = pose.rotation();
  for (size_t i = 0; i < points.size(); ++i) {
    const Match& m = matches_[i];
    const double distance =
        m.valid ? m.normal.dot(rotation * points[i] + pose.translation() - m.point) : std::nan("");
    out->push_back(distance / sigma_[i]);
    if (gates) gates->push_back(config.gate_m / sigma_[i]);
  }
}

}  // namespace houghloc
