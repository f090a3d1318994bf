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

  /// The status message: counters, the last image's figures, what is wrong now.
  localizer_status_t status() const;
  const DropCounters& drops() const { return drops_; }

 private:
  void drop(DropReason reason, const std::string& message);

  LocalizationPipeline pipeline_;
  std::map<std::string, CameraIntrinsics> cameras_;
  NodeTimingConfig timing_;
  StampedBuffer<Pose2> odometry_;
  std::map<std::string, StampedBuffer<Pose3>> camera_poses_;
  std::map<std::string, std::int64_t> last_image_utime_;
  DropCounters drops_;
  std::string problem_;  ///< the last refusal, named
  std::int64_t frames_processed_ = 0;
  std::int64_t last_utime_ = 0;
  double last_cycle_ms_ = 0.0;
  LocalizationEstimate last_estimate_;
};

}  // namespace houghloc
