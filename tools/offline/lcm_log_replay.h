#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose3.h"
#include "tools/offline/estimate_csv.h"
#include "tools/pipeline/localization_pipeline.h"
#include "tools/recording/recording.h"

namespace houghloc {

/// What houghloc-offline --lcm-log replays: an lcm-logger log of houghloc-node's channels.
struct LogReplayInput {
  std::string log_path;
  std::string channel_prefix;  ///< as the node's --channel-prefix
  std::shared_ptr<const FieldModel> field;
  PipelineConfig config;                             ///< composed as houghloc-node composes it
  std::map<std::string, CameraIntrinsics> cameras;   ///< per camera id, as --camera-yaml
  std::map<std::string, Pose3> static_camera_poses;  ///< the node's config static_camera_pose
  std::string config_file;                           ///< where they come from, for errors
};

/// The replay's outputs and how they compare with the node's logged HYPOTHESES.
struct LogReplayResult {
  std::vector<FrameEstimate> estimates;         ///< one per processed image, in processing order
  std::vector<FrameRecord> frames;              ///< t_us and camera id of each (no image, no poses)
  std::vector<GroundTruthRecord> ground_truth;  ///< GROUND_TRUTH messages, by t_us
  int images = 0;                               ///< IMAGE messages in the log
  int logged_hypotheses = 0;                    ///< HYPOTHESES messages in the log
  int refused = 0;            ///< images with HYPOTHESES that the node's core refused here
  std::string first_refusal;  ///< why, for the first of them
  /// Largest difference to the logged HYPOTHESES of the same utime over x, y, theta (wrapped),
  /// covariance and weight of every hypothesis (m, rad, ...).
  double max_difference = 0.0;
  int mismatches = 0;  ///< images whose status or number of hypotheses differ from the logged
  std::int64_t truncated_at = -1;  ///< byte offset of a last event cut short; -1: none
};

/// Replays the log through houghloc-node's core (NodeCore: the same checks, interpolation
/// buffers and LocalizationPipeline as the node): ODOMETRY, CAMERA_POSE and HINT in log order,
/// and exactly the IMAGE messages for which the log holds a HYPOTHESES message with the same
/// utime (the images the node processed), each at its place in the log. `progress` gets the
/// number of images processed so far and the number of logged HYPOTHESES. Throws LcmLogError for a
/// file that is not an LCM log.
LogReplayResult replayLcmLog(const LogReplayInput& input,
                             const std::function<void(int, int)>& progress = {});

}  // namespace houghloc
