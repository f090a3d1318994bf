#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose2.h"
#include "field_models/pose3.h"
#include "vision/camera_model.h"

namespace houghloc {

/// An error in a recorded folder; what() names the file and, where it applies, the line.
class RecordingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One row of frames.csv (DESIGN §5.1).
struct FrameRecord {
  std::string image;  ///< path relative to the folder
  std::int64_t t_us = 0;
  /// Cumulative odometry pose; none when the row leaves odom_x, odom_y and odom_theta empty (no
  /// odometry received for this frame, as the node sees it when none lies near the image).
  std::optional<Pose2> odometry = Pose2();
  Pose3 robot_T_camera;   ///< recorded camera pose (head motion)
  std::string camera_id;  ///< empty: camera.yaml; else cameras/<id>.yaml
};

struct GroundTruthRecord {
  std::int64_t t_us = 0;
  Pose2 field_T_robot;
};

/// One row of hints.csv; kind is UNKNOWN, RESET_TO, ADD, OWN_HALF or MIRROR (DESIGN §7).
struct HintRecord {
  std::int64_t t_us = 0;
  std::string kind;
  std::optional<Pose2> pose;                               ///< empty when the row leaves it empty
  double sigma_x = 0.0, sigma_y = 0.0, sigma_theta = 0.0;  ///< m, m, rad
};

/// One row of truth/visible.csv: how much of a map feature is really visible (unoccluded,
/// within 4 m) in that frame.
struct VisibleRecord {
  std::int64_t t_us = 0;
  std::string feature;  ///< e.g. "segments[3]", "arcs[0]", "marks[1]"
  double visible_length_m = 0.0;
  double direction_deg = 0.0;  ///< field-frame direction of a segment in [0, 180); arcs: 0
};

/// One row of truth/events.csv: KIDNAP, FALL_START or FALL_END.
struct EventRecord {
  std::int64_t t_us = 0;
  std::string event;
};

/// A recorded image folder in memory (DESIGN §5.1); images stay on disk.
struct Recording {
  std::string folder;
  std::optional<CameraIntrinsics> camera;           ///< camera.yaml
  std::map<std::string, CameraIntrinsics> cameras;  ///< cameras/<id>.yaml
  std::vector<FrameRecord> frames;
  std::vector<GroundTruthRecord> ground_truth;
  std::vector<HintRecord> hints;
  std::optional<FieldModel> field;     ///< field.yaml
  std::vector<VisibleRecord> visible;  ///< truth/visible.csv
  std::vector<EventRecord> events;     ///< truth/events.csv

  /// Intrinsics for a frame's camera id; throws RecordingError when they are missing.
  const CameraIntrinsics& intrinsicsFor(const FrameRecord& frame) const;
};

/// Reads every file of the folder that exists (frames.csv and a camera are required). Throws
/// RecordingError naming file and line for malformed rows, non-numeric fields, times going
/// backwards, odometry fields only partly empty, unknown hint kinds and missing required files.
Recording readRecording(const std::string& folder);

/// Writes the folder's CSV and YAML files (not the images); creates folders as needed.
void writeRecording(const Recording& recording, const std::string& folder);

/// Ground truth at t_us, linearly interpolated between the rows around it (angles on the
/// circle); none when no row lies within tolerance_us of t_us.
std::optional<Pose2> groundTruthAt(const std::vector<GroundTruthRecord>& truth, std::int64_t t_us,
                                   std::int64_t tolerance_us = 20000);

}  // namespace houghloc
