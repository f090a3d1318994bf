#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "field_models/ground_points.h"
#include "field_models/pose3.h"
#include "vision/camera_model.h"
#include "vision/camera_pose_corrector.h"
#include "vision/field_boundary.h"
#include "vision/field_color.h"
#include "vision/field_edge.h"
#include "vision/field_top_pitch.h"
#include "vision/ground_projection.h"
#include "vision/horizon.h"
#include "vision/line_segments.h"
#include "vision/line_spots.h"
#include "vision/line_width_model.h"
#include "vision/own_body.h"
#include "vision/scan_grid.h"
#include "vision/width_pitch.h"

namespace houghloc {

/// Every vision tunable; the config file's `vision:` section has one sub-map per member.
struct VisionConfig {
  double line_width_m = 0.05;  ///< painted line width, normally taken from the map
  HorizonConfig horizon;
  FieldColorConfig field_color;
  FieldBoundaryConfig boundary;
  LineWidthModelConfig line_width;
  ScanGridConfig scan_grid;
  LineSpotConfig spots;
  GroundProjectionConfig projection;
  OwnBodyConfig own_body;
  FieldEdgeSamplingConfig field_edge;
  LineSegmentConfig segments;
  CameraPoseCorrectionConfig pose_correction;
  WidthPitchConfig width_pitch;  ///< a frame whose candidates are all too wide: fit the pitch
  FieldTopPitchConfig field_top_pitch;  ///< a frame whose turf reaches above the horizon: pitch
};

/// Per-step times and counts of one frame, for tuning and the offline summary.
struct VisionDiagnostics {
  FieldColor field_color;
  LineSpotStats spot_stats;
  ProjectionStats projection_stats;
  int num_spots = 0;
  int dropped_near_boundary = 0;  ///< spots within min_boundary_gap_m of the field boundary
  int dropped_on_own_body = 0;    ///< spots on the robot's own feet (OwnBodyConfig)
  int dropped_isolated = 0;       ///< then spots with no other near them (SpotSupportConfig)
  bool pose_correction_updated = false;
  Eigen::Vector2d pose_correction_rad = Eigen::Vector2d::Zero();  ///< (roll, pitch) applied
  /// The corrector's estimate before its significance gate, and its standard deviation (rad;
  /// infinite before the first solve).
  Eigen::Vector2d pose_correction_estimate_rad = Eigen::Vector2d::Zero();
  Eigen::Vector2d pose_correction_sigma_rad =
      Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  int pose_correction_map_inliers = 0;  ///< this frame's points matched to the map (0: none)
  /// Pitch offsets (rad) the image of a frame without spots asked for, added to its recorded
  /// pose before a new scan (0: none): the widths of its too-wide candidates (width_pitch.h),
  /// and its turf seen above the computed horizon (field_top_pitch.h; plus what the widths of the
  /// lines then found add within FieldTopPitchConfig::max_shortfall_rad).
  double width_pitch_rad = 0.0;
  double field_top_pitch_rad = 0.0;
  double time_total_ms = 0.0;
  double time_color_ms = 0.0;     ///< horizon, field colour, boundary
  double time_spots_ms = 0.0;     ///< width model, scan grid, spot detection, pitch rescans
  double time_project_ms = 0.0;   ///< projection, visible region
  double time_features_ms = 0.0;  ///< rays, segments, circles, pose correction
};

struct VisionResult {
  GroundPoints ground;               ///< line points and visible region, robot frame
  std::vector<double> horizon_rows;  ///< per column, from the corrected camera pose
  FieldBoundary boundary;            ///< field boundary per column
  std::vector<LineSpot> spots;       ///< accepted spots before projection and thinning
  LineFeatures features;             ///< short segments and centre-circle candidates
  Pose3 robot_T_camera_used;         ///< the recorded pose plus the online correction
  VisionDiagnostics diagnostics;
};

/// Image + camera pose -> ground points (DESIGN §2). Keeps the camera model and the online
/// pitch/roll correction between frames; otherwise every frame stands alone.
class VisionPipeline {
 public:
  /// Throws std::invalid_argument for invalid intrinsics.
  explicit VisionPipeline(const CameraIntrinsics& intrinsics, const VisionConfig& config = {},
                          int camera_id = 0);

  /// image: BGR8 (CV_8UC3) or YUYV (CV_8UC2, even width) of the intrinsics' size; YUYV is not
  /// converted as a whole, each stage decodes the pixels it reads (pixel_access.h). Throws
  /// std::invalid_argument for another size or type and for a non-finite camera pose.
  /// field_T_robot: where the localizer puts the robot at this frame (its track, predicted
  /// with odometry), when it has one; with setFieldModel it lets the pitch/roll corrector match
  /// the line points to the map.
  VisionResult process(const cv::Mat& image, const Pose3& robot_T_camera, std::int64_t t_us = 0,
                       const std::optional<Pose2>& field_T_robot = std::nullopt);

  /// The map the pitch/roll corrector matches points against in frames with a field pose.
  void setFieldModel(std::shared_ptr<const FieldModel> field) {
    corrector_->setFieldModel(std::move(field));
  }

  /// From now on this pipeline and `other` estimate one pitch/roll correction together, from
  /// both cameras' lines (each frame keeps its own recorded pose): for cameras whose recorded
  /// poses are off by the same roll and pitch, e.g. a head joint offset on a NAO, whose bottom
  /// camera alone sees too little to find its own (CameraPoseCorrectionConfig::
  /// shared_between_cameras). This pipeline's estimate so far is dropped; the two must not
  /// process() at the same time, and resetPoseCorrection() on either resets both.
  void sharePoseCorrection(const VisionPipeline& other) { corrector_ = other.corrector_; }

  const VisionConfig& config() const { return config_; }
  const CameraModel& camera() const { return camera_; }
  const CameraPoseCorrector& poseCorrector() const { return *corrector_; }
  void resetPoseCorrection() { corrector_->reset(); }

 private:
  /// Points camera_ at `pose` (the corrected recorded pose) and writes it and the horizon into
  /// `result`.
  void usePose(const Pose3& pose, VisionResult* result);
  /// Adds `offset` (rad) to the recorded pose's pitch and points camera_, the pose and the scan
  /// start rows at it.
  void addPitch(double offset, Pose3* recorded, Pose3* pose, std::vector<int>* start_rows,
                VisionResult* result);
  /// A pitch offset (rad) the image asks for, and the diagnostic that sums it.
  struct PitchRequest {
    double offset_rad;
    double VisionDiagnostics::*diagnostic;
  };
  /// For a frame whose spots form no line (`result` after its scan from `start_rows`): the
  /// pitch under which its too-wide candidates have a line's width (a frame without spots), else
  /// the pitch that puts its turf seen above the computed horizon below it; none when neither
  /// asks for one.
  std::optional<PitchRequest> pitchTheImageAsksFor(const cv::Mat& image, const VisionResult& result,
                                                   const std::vector<int>& start_rows) const;
  /// Steps 5-6 on result's spots with camera_'s pose (`pose`): their undistorted rays but those
  /// on the robot's own body (returned), and the segments and circles they form (into result).
  std::vector<SpotRay> fitFeatures(const Pose3& pose, VisionResult* result) const;
  /// Whether a frame shows line evidence: a segment or a centre-circle arc. Specks of turf, a
  /// ball or a robot's parts give spots but rarely four in a straight line on the ground.
  static bool formsLines(const LineFeatures& features);
  /// Steps 3-4 with camera_'s pose and the frame's field colour: the field boundary below
  /// `start_rows`, the width model, the scan grid and the line spots, into `result`.
  /// pitch_shortfall_rad > 0: the pose's pitch is a lower bound that the real pitch may exceed by
  /// this much; runs as wide as a line under the steeper pitch pass the width test.
  void findSpots(const cv::Mat& image, const std::vector<int>& start_rows, VisionResult* result,
                 double pitch_shortfall_rad = 0.0) const;

  VisionConfig config_;
  int camera_id_ = 0;
  CameraModel camera_;
  std::shared_ptr<CameraPoseCorrector> corrector_;  ///< shared by sharePoseCorrection()
  FieldColor last_field_color_;  ///< this camera's last valid field colour (frame memory)
  int field_color_age_ = std::numeric_limits<int>::max() / 2;  ///< frames since it
};

}  // namespace houghloc
