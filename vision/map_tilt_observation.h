#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose2.h"
#include "field_models/pose3.h"

namespace houghloc {

struct MapTiltConfig {
  bool enabled = true;              ///< used only in frames that come with a field pose
  int max_points_per_frame = 40;    ///< spread evenly over the frame's points (bounds the cost)
  double max_range_m = 4.0;         ///< farther points are too noisy to help
  double search_radius_m = 0.3;     ///< first association, around the given field pose (the
                                    ///< localizer's track is good to a few cm; a tilt still
                                    ///< degrees off moves points at 3 m by up to 0.3 m)
  double gate_m = 0.06;             ///< after the frame's pose fit: farther points are no
                                    ///< line points (robots' feet, lines beyond the field)
  int min_inliers = 12;             ///< fewer matched points: the frame's pose absorbs them
  double min_inlier_share = 0.7;    ///< of the frame's points; fewer: the given pose is wrong
                                    ///< (or the tilt still far off), and a few lines that
                                    ///< happen to pass near points would bend the estimate
  int pose_fit_iterations = 4;      ///< Gauss-Newton steps of the frame's field pose
  double max_pose_shift_m = 0.15;   ///< the fitted pose must stay this close to the given one
  double max_pose_turn_rad = 0.05;  ///< (3 deg); farther, the given pose was wrong and the fit
                                    ///< found some other lines that happen to fit
  int min_points_per_line = 3;      ///< matches on a second line (or an arc) needed: points on
                                    ///< one line leave the tilt to numerical noise (showsTilt)
  double min_spread_m = 1.0;        ///< extent of the matched points (bounding-box diagonal):
                                    ///< in a smaller patch (a NAO's bottom camera sees 0.2-0.6 m
                                    ///< ahead) the fitted pose's turn and shift mimic a tilt, and
                                    ///< the fit turned numerical noise into a confident 2 deg
};

/// One frame's line points matched to the field map near a field pose that comes from outside
/// (the localizer's track): with the map, every point's distance to its line depends on the
/// camera tilt, not only the lines' directions. A pitch error scales the ground with range
/// (points at 3 m move (d^2 + h^2) / h times the angle), a roll error skews it; no rigid pose
/// explains that, so the frame's own field pose, fitted anew for every tilt tried, leaves it in
/// the residuals. The given pose only seeds the association; a wrong or mirrored one costs
/// nothing on a symmetric field, and one far off finds too few inliers and is dropped.
class MapTiltObservation {
 public:
  /// rays: line spots' viewing rays in the camera frame; sigma_m: each one's ground noise.
  MapTiltObservation(std::vector<Eigen::Vector3d> rays_camera, std::vector<double> sigma_m,
                     const Pose2& field_T_robot_guess);

  /// Matches every point within max_range_m, projected with robot_T_camera, to its nearest map
  /// line (segments and arcs; marks are too small to carry a direction) twice, refitting the
  /// frame's field pose in between; returns the number of inliers (0 when the frame fails a
  /// gate). The matches stay fixed until the next call.
  int associate(const FieldModel& field, const Pose3& robot_T_camera, const MapTiltConfig& config,
                double max_range_m);

  /// Whitened distances (residual / sigma) of the matched points to their lines after fitting
  /// the frame's field pose to them, with the points projected by robot_T_camera; NaN for
  /// unmatched points. `gates` (optional) receives config.gate_m in sigmas per point.
  void residuals(const Pose3& robot_T_camera, const MapTiltConfig& config, std::vector<double>* out,
                 std::vector<double>* gates) const;

  int inliers() const { return inliers_; }

 private:
  /// A matched point's line, linearised at the closest point: field frame, unit normal.
  struct Match {
    Eigen::Vector2d point = Eigen::Vector2d::Zero();
    Eigen::Vector2d normal = Eigen::Vector2d::Zero();
    FeatureRef feature;  ///< the map line or arc
    bool valid = false;
  };

  /// Whether the matches can show a tilt at all once the frame's pose is fitted: points on a
  /// single straight line cannot (a line has two degrees of freedom, the pose three), so they
  /// must lie on two lines or on an arc, each with min_points_per_line matches, and spread
  /// over min_spread_m (`points`: robot frame).
  bool showsTilt(const std::vector<Eigen::Vector2d>& points, const MapTiltConfig& config) const;

  std::vector<Eigen::Vector2d> project(const Pose3& robot_T_camera) const;
  /// The field pose that best fits `points` to their matches, from `start`.
  Pose2 fitPose(const std::vector<Eigen::Vector2d>& points, const Pose2& start,
                int iterations) const;
  /// Matches the points within max_range_m; returns how many were tried.
  int match(const FieldModel& field, const std::vector<Eigen::Vector2d>& points,
            const Pose2& field_T_robot, double radius_m, double max_range_m);

  std::vector<Eigen::Vector3d> rays_;
  std::vector<double> sigma_;
  Pose2 guess_;
  Pose2 fitted_;  ///< by associate(): where residuals() starts its fit
  std::vector<Match> matches_;
  int inliers_ = 0;
};

}  // namespace houghloc
