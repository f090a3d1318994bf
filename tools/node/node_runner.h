#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <mutex>
#include <string>

#include "tools/node/node_core.h"
#include "tools/node/node_log.h"
#include "tools/node/pose_file.h"

namespace houghloc {

/// What NodeRunner does besides moving messages.
struct NodeRunnerOptions {
  std::string save_pose;  ///< --save-pose FILE; empty: none
  PoseFileConfig pose_file;
  NodeLog* log = nullptr;  ///< none: prints nothing
};

/// houghloc-node's transport: LCM handling on one thread (decode, queue), processing on another
/// (NodeCore). Small messages are applied in arrival order before the next image; of the images
/// waiting, each camera keeps only its newest (older ones are counted as queue full), and the
/// oldest utime across cameras is processed first. Images may also come from other threads
/// (submitImage(): a grabbed device). With save_pose set, the best pose is written every
/// save_period_s while TRACKING or AMBIGUOUS and once more at the end.
class NodeRunner {
 public:
  NodeRunner(lcm::LCM& lcm, NodeCore& core, const std::string& channel_prefix,
             bool publish_line_points, const NodeRunnerOptions& options = {});
  /// Runs both threads until `stop` is set, then publishes a last STATUS; returns within ~0.2 s.
  void run(const std::atomic<bool>& stop);

  /// An image as if it had arrived on <PREFIX>IMAGE; any thread.
  void submitImage(image_t image);
  /// A condition for the status message (empty text clears it); any thread.
  void setCondition(const std::string& key, const std::string& text);

 private:
  void subscribe(const std::string& channel, std::function<void(const lcm::ReceiveBuffer&)> f);
  /// LCM's raw callback for every subscribed channel: the payload is decoded by the channel's
  /// handler, so that a message that does not decode is counted instead of silently skipped.
  void onRaw(const lcm::ReceiveBuffer* buf, const std::string& channel);
  template <typename T>
  bool decode(const lcm::ReceiveBuffer& buf, T& msg);
  void processLoop(const std::atomic<bool>& stop);
  void publishStatus(const localizer_status_t& status);
  void savePose();

  lcm::LCM& lcm_;
  NodeCore& core_;
  std::string prefix_;
  bool publish_line_points_;
  NodeRunnerOptions options_;

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void(NodeCore&)>> small_;  ///< odometry, camera poses, hints
  std::map<std::string, image_t> images_;             ///< newest waiting image per camera
  std::map<std::string, std::string> conditions_;     ///< from other threads; "" clears
  std::int64_t undecodable_ = 0, replaced_ = 0;       ///< counted on the LCM thread
  std::int8_t last_state_ = -1;
  std::string last_message_;
  /// Per full channel name; filled in the constructor, read on the LCM thread only.
  std::map<std::string, std::function<void(const lcm::ReceiveBuffer&)>> handlers_;
};

}  // namespace houghloc
