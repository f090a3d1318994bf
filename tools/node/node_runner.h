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

namespace houghloc {

/// houghloc-node's transport: LCM handling on one thread (decode, queue), processing on another
/// (NodeCore). Small messages are applied in arrival order before the next image; of the images
/// waiting, each camera keeps only its newest (older ones are counted as queue full), and the
/// oldest utime across cameras is processed first.
class NodeRunner {
 public:
  NodeRunner(lcm::LCM& lcm, NodeCore& core, const std::string& channel_prefix,
             bool publish_line_points);
  /// Runs both threads until `stop` is set; returns within ~0.2 s of that.
  void run(const std::atomic<bool>& stop);

 private:
  void subscribe(const std::string& channel, std::function<void(const lcm::ReceiveBuffer&)> f);
  /// LCM's raw callback for every subscribed channel: the payload is decoded by the channel's
  /// handler, so that a message that does not decode is counted instead of silently skipped.
  void onRaw(const lcm::ReceiveBuffer* buf, const std::string& channel);
  template <typename T>
  bool decode(const lcm::ReceiveBuffer& buf, T& msg);
  void processLoop(const std::atomic<bool>& stop);
  void publishStatus();

  lcm::LCM& lcm_;
  NodeCore& core_;
  std::string prefix_;
  bool publish_line_points_;

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void(NodeCore&)>> small_;  ///< odometry, camera poses, hints
  std::map<std::string, image_t> images_;             ///< newest waiting image per camera
  std::int64_t undecodable_ = 0, replaced_ = 0;       ///< counted on the LCM thread
  std::int8_t last_state_ = -1;
  /// Per full channel name; filled in the constructor, read on the LCM thread only.
  std::map<std::string, std::function<void(const lcm::ReceiveBuffer&)>> handlers_;
};

}  // namespace houghloc
