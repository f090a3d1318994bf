#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "houghloc/camera_pose_t.hpp"
#include "houghloc/image_t.hpp"
#include "houghloc/line_points_t.hpp"
#include "houghloc/localization_hint_t.hpp"
#include "houghloc/localizer_status_t.hpp"
#include "houghloc/odometry_t.hpp"
#include "houghloc/pose_hypotheses_t.hpp"
#include "tools/lcm/drop_counters.h"
#include "tools/lcm/stamped_buffer.h"
#include "tools/pipeline/localization_pipeline.h"

namespace houghloc {

/// Time rules of houghloc-node (DESIGN §7), microseconds of the publisher's clock.
struct NodeTimingConfig {
  std::int64_t max_camera_pose_gap_us = 50'000;  ///< no camera pose this near: image dropped
  std::int64_t max_odometry_gap_us = 100'000;    ///< no odometry this near: frame without motion
  /// Streams (odometry, a camera's poses, another camera's images) whose newest utime lies
  /// farther than this from the newest image are named in the status message.
  std::int64_t max_stream_gap_us = 1'000'000;
  /// An image older than the last one of its camera by more than this means the publisher
  /// restarted with a new clock: the image is processed and the restart counted. Closer older
  /// images are dropped as old.
  std::int64_t restart_gap_us = 1'000'000;
};

/// What one processed image gives: HYPOTHESES and LINE_POINTS, both with the image's utime.
struct NodeOutput {
  pose_hypotheses_t hypotheses;
  line_points_t line_points;
};

/// houghloc-node's logic without LCM, threads or clocks: handlers take decoded messages, so
/// tests and fuzzers drive it in-process. Inputs are checked here (sizes, NaN, times) and every
/// refusal is counted; LocalizationPipeline (kFull) does the vision and localization.
class NodeCore {
 public:
  NodeCore(std::shared_ptr<const FieldModel> field, const PipelineConfig& config,
           const std::map<std::string, CameraIntrinsics>& cameras,
           const NodeTimingConfig& timing = {});

  void onOdometry(const odometry_t& msg);
  void onCameraPose(const camera_pose_t& msg);
  void onHint(const localization_hint_t& msg);
  /// Processes the image, or counts why not and returns none.
  std::optional<NodeOutput> onImage(const image_t& msg);
  /// A message that did not decode (any channel).
  void onUndecodable() { drops_.add(DropReason::kMalformed); }
  /// An image replaced by a newer one of its camera before processing (the node's queue).
  void onReplaced() { drops_.add(DropReason::kQueueFull); }

  /// robot_T_camera of a camera without head joints (config node: static_camera_pose): used
  /// for its images when no camera_pose_t of that camera lies within 50 ms.
  void setStaticCameraPose(const std::string& camera_id, const Pose3& robot_T_camera);
  /// setStaticCameraPose() for each of `poses` (node: static_camera_pose of `config_file`);
  /// throws std::runtime_error naming the file and key for a camera without a camera.yaml.
  void setStaticCameraPoses(const std::map<std::string, Pose3>& poses,
                            const std::string& config_file);
  /// A pose saved before a restart (--save-pose), as a RESET_TO hint before the first image.
  void restorePose(const GaussianPose& field_T_robot);
  /// A condition outside the core (a device that cannot be opened, say), shown in the status
  /// message under `key` until cleared.
  void setCondition(const std::string& key, const std::string& text);
  void clearCondition(const std::string& key) { conditions_.erase(key); }

  /// The estimate of the last processed image.
  const LocalizationEstimate& estimate() const { return last_estimate_; }
  /// Times an image's utime went back by more than restart_gap_us (a restarted publisher).
  int restarts() const { return restarts_; }

  /// The status message: counters, the last image's figures, what is wrong now.
  localizer_status_t status() const;
  const DropCounters& drops() const { return drops_; }

 private:
  void drop(DropReason reason, const std::string& message);
  /// Drops (malformed) a message whose utime no clock gives, naming it by `kind` and, for a
  /// camera's message, the camera; true if so. The name is built only for a refused message.
  bool refuseTime(std::int64_t utime, const char* kind, const std::string* camera_id = nullptr);
  /// Odometry, camera poses and images of other cameras farther than max_stream_gap_us from
  /// the newest image, as text for the status message.
  std::string streamGaps() const;

  LocalizationPipeline pipeline_;
  std::map<std::string, CameraIntrinsics> cameras_;
  NodeTimingConfig timing_;
  StampedBuffer<Pose2> odometry_;
  std::map<std::string, StampedBuffer<Pose3>> camera_poses_;
  std::map<std::string, Pose3> static_camera_poses_;
  std::map<std::string, std::int64_t> last_image_utime_;    ///< processed, per camera
  std::map<std::string, std::int64_t> newest_image_utime_;  ///< received, per camera
  std::map<std::string, std::string> conditions_;
  int restarts_ = 0;
  std::string restart_text_;
  DropCounters drops_;
  std::string problem_;             ///< the last refusal, named
  std::int64_t problem_utime_ = 0;  ///< the newest image utime when it happened
  std::int64_t frames_processed_ = 0;
  std::int64_t last_utime_ = 0;
  double last_cycle_ms_ = 0.0;
  LocalizationEstimate last_estimate_;
};

}  // namespace houghloc
