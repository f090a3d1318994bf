#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/ground_points.h"
#include "field_models/pose2.h"
#include "tools/recording/recording.h"
#include "vision/camera_model.h"

namespace houghloc {

struct VisionMetricsConfig {
  double precision_radius_m = 0.05;  ///< a point within this of a true line is a true positive
  double recall_radius_m = 0.10;     ///< a visible line sample with a point this close is found
  double sample_step_m = 0.10;       ///< line sampling for recall
  std::vector<double> band_edges_m = {0.0, 2.0, 3.0, 4.0};  ///< distance bands from the robot
};

struct VisionBandMetrics {
  double min_m = 0.0, max_m = 0.0;
  long points = 0;          ///< detected points in the band
  long true_positives = 0;  ///< ... within precision_radius_m of a true line
  double visible_m = 0.0;   ///< visible, unoccluded line length in view (truth/visible.csv)
  double found_m = 0.0;     ///< ... with a detected point within recall_radius_m
  double precision = 0.0, recall = 0.0;
  double median_error_m = 0.0, p95_error_m = 0.0;  ///< ground error of the true positives
};

/// GroundPoints::field_edge against the carpet's edge at the true pose, along each sample's ray
/// from the camera (error > 0: seen farther than the edge).
struct FieldEdgeMetrics {
  long samples = 0;
  double median_abs_error_m = 0.0;
  double median_abs_error_sigmas = 0.0;  ///< |error| / the sample's range_sigma_m
  double within_3_sigma = 0.0;           ///< share of samples
  double nearer_share = 0.0;   ///< share more than 3 sigma nearer (something on the field)
  double farther_share = 0.0;  ///< share more than 3 sigma farther (green beyond the carpet)
};

struct VisionMetrics {
  int frames_scored = 0;
  long points = 0, true_positives = 0;
  double precision = 0.0;
  std::vector<VisionBandMetrics> bands;
  FieldEdgeMetrics field_edge;
};

/// Accumulates DESIGN/issue-5 vision metrics over frames. Precision: share of points within
/// 5 cm of a map line at the ground-truth pose. Recall: every feature truth/visible.csv lists for
/// the frame is sampled every 10 cm; samples within the camera's view (projecting inside the
/// image, within the last band) count as visible, scaled by visible_length_m / in-view length when
/// the renderer reports part of it occluded; a sample is found when a point lies within 10 cm.
class VisionMetricsAccumulator {
 public:
  explicit VisionMetricsAccumulator(const FieldModel& field,
                                    const VisionMetricsConfig& config = {});

  /// camera: posed at the frame's (exact) robot_T_camera.
  void addFrame(const GroundPoints& points, const Pose2& field_T_robot,
                const std::vector<VisibleRecord>& visible, const CameraModel& camera);

  VisionMetrics result() const;

 private:
  struct Band {
    long points = 0, true_positives = 0;
    double visible_m = 0.0, found_m = 0.0;
    std::vector<double> errors;
  };
  int bandOf(double range_m) const;
  std::vector<Eigen::Vector2d> featureSamples(const std::string& feature) const;

  FieldModel field_;
  VisionMetricsConfig config_;
  int frames_ = 0;
  long points_ = 0, true_positives_ = 0;
  std::vector<Band> bands_;
  std::vector<double> edge_errors_m_, edge_errors_sigmas_;  ///< signed
};

nlohmann::json toJson(const VisionMetrics& metrics);

/// Rows of truth/visible.csv with this t_us (the renderer writes the frame's own timestamp).
std::vector<VisibleRecord> visibleAt(const std::vector<VisibleRecord>& visible, std::int64_t t_us);

}  // namespace houghloc
