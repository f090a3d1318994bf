#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose2.h"
#include "vision/camera_model.h"

namespace houghloc {

/// How a frame's ground points are scored against the map at a ground-truth field pose (the
/// real frames with a groundtruth.csv pose).
struct GroundTruthMetricsConfig {
  /// A point with |x| > half length + this is beyond a goal line.
  double beyond_goal_margin_m = 0.1;
  double sample_step_m = 0.05;   ///< map lines and arcs are sampled this often for coverage
  double max_range_m = 5.0;      ///< samples farther from the robot are not counted
  double found_radius_m = 0.15;  ///< a sample with a point this close is covered
};

struct GroundTruthMetrics {
  int points = 0;
  /// Median distance of the points (field frame) to the nearest map feature (nearestFeature());
  /// NaN without points.
  double median_distance_m = 0.0;
  int beyond_goal = 0;  ///< points more than beyond_goal_margin_m beyond a goal line
  double beyond_goal_share = 0.0;
  int visible_samples = 0;  ///< map samples in view (visibleLineSamples())
  int covered_samples = 0;  ///< ... with a point within found_radius_m
  double coverage = 0.0;    ///< covered / visible; NaN when nothing is in view
};

/// Median distance (m) of robot-frame points, placed at field_T_robot, to the nearest line
/// feature of the map (segments, arcs, marks); NaN for no points.
double medianMapDistance(const FieldModel& field, const Pose2& field_T_robot,
                         const std::vector<Eigen::Vector2d>& points_robot);

/// Points whose field x lies more than margin_m beyond a goal line (|x| > half length + margin).
int countBeyondGoalLine(const FieldModel& field, const Pose2& field_T_robot,
                        const std::vector<Eigen::Vector2d>& points_robot, double margin_m);

/// The map's segments and arcs sampled every sample_step_m (field frame), returned in the robot
/// frame: those within max_range_m of the robot whose ground point projects inside the image
/// and below the horizon of `camera` (posed at the frame's robot_T_camera).
std::vector<Eigen::Vector2d> visibleLineSamples(const FieldModel& field, const Pose2& field_T_robot,
                                                const CameraModel& camera,
                                                const GroundTruthMetricsConfig& config = {});

/// Samples with a point within radius_m (robot frame).
int countCoveredSamples(const std::vector<Eigen::Vector2d>& samples_robot,
                        const std::vector<Eigen::Vector2d>& points_robot, double radius_m);

/// All of the above for one frame.
GroundTruthMetrics groundTruthMetrics(const FieldModel& field, const Pose2& field_T_robot,
                                      const CameraModel& camera,
                                      const std::vector<Eigen::Vector2d>& points_robot,
                                      const GroundTruthMetricsConfig& config = {});

}  // namespace houghloc
