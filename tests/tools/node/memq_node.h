// NodeRunner on a memq:// LCM and a thread of its own, as houghloc-node runs it (its LCM thread
// and processing thread), for the in-process node tests. A test subscribes its handlers on
// lcm() first, then calls start(); the destructor stops and joins, so declare the MemqNode after
// everything its handlers touch.
#pragma once

#include <atomic>
#include <cstdint>
#include <lcm/lcm-cpp.hpp>
#include <string>
#include <thread>
#include <vector>

#include "tools/node/node_runner.h"

namespace houghloc {

class MemqNode {
 public:
  explicit MemqNode(NodeCore& core, const NodeRunnerOptions& options = {})
      : lcm_("memq://"), runner_(lcm_, core, "", true, options) {}
  ~MemqNode() { stop(); }
  MemqNode(const MemqNode&) = delete;
  MemqNode& operator=(const MemqNode&) = delete;

  void start() {
    thread_ = std::thread([this] { runner_.run(stop_); });
  }
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  template <typename T>
  void publish(const std::string& channel, const T& msg) {
    lcm_.publish(channel, &msg);
  }
  void publishRaw(const std::string& channel, const std::vector<std::uint8_t>& bytes) {
    lcm_.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
  }
  lcm::LCM& lcm() { return lcm_; }
  NodeRunner& runner() { return runner_; }

 private:
  lcm::LCM lcm_;
  NodeRunner runner_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace houghloc
