#include "tools/node/node_runner.h"

#include <chrono>
#include <thread>

#include "tools/lcm/message_decoding.h"

namespace houghloc {
namespace {

using SteadyClock = std::chrono::steady_clock;

}  // namespace

NodeRunner::NodeRunner(lcm::LCM& lcm, NodeCore& core, const std::string& channel_prefix,
                       bool publish_line_points)
    : lcm_(lcm), core_(core), prefix_(channel_prefix), publish_line_points_(publish_line_points) {
  auto small = [this](auto msg, void (NodeCore::*on)(const decltype(msg)&)) {
    return [this, on](const lcm::ReceiveBuffer& buf) {
      decltype(msg) m;
      if (!decode(buf, m)) return;
      std::lock_guard<std::mutex> lock(mutex_);
      small_.push_back([m, on](NodeCore& core) { (core.*on)(m); });
      wake_.notify_one();
    };
  };
  subscribe("ODOMETRY", small(odometry_t{}, &NodeCore::onOdometry));
  subscribe("CAMERA_POSE", small(camera_pose_t{}, &NodeCore::onCameraPose));
  subscribe("HINT", small(localization_hint_t{}, &NodeCore::onHint));
  subscribe("IMAGE", [this](const lcm::ReceiveBuffer& buf) {
    image_t m;
    if (!decode(buf, m)) return;
    std::lock_guard<std::mutex> lock(mutex_);
    auto [it, inserted] = images_.try_emplace(m.camera_id);
    if (!inserted) ++replaced_;  // the newest image of a camera wins
    it->second = std::move(m);
    wake_.notify_one();
  });
}

void NodeRunner::subscribe(const std::string& channel,
                           std::function<void(const lcm::ReceiveBuffer&)> f) {
  handlers_[prefix_ + channel] = std::move(f);
  lcm_.subscribe(prefix_ + channel, &NodeRunner::onRaw, this);
}

void NodeRunner::onRaw(const lcm::ReceiveBuffer* buf, const std::string& channel) {
  const auto it = handlers_.find(channel);
  if (it != handlers_.end()) it->second(*buf);
}

template <typename T>
bool NodeRunner::decode(const lcm::ReceiveBuffer& buf, T& msg) {
  if (decodeMessage(buf.data, buf.data_size, msg)) return true;
  std::lock_guard<std::mutex> lock(mutex_);
  ++undecodable_;
  return false;
}

void NodeRunner::run(const std::atomic<bool>& stop) {
  std::thread processing([this, &stop] { processLoop(stop); });
  while (!stop) lcm_.handleTimeout(100);
  wake_.notify_all();
  processing.join();
}

void NodeRunner::processLoop(const std::atomic<bool>& stop) {
  auto next_status = SteadyClock::now();
  while (!stop) {
    std::deque<std::function<void(NodeCore&)>> small;
    std::optional<image_t> image;
    std::int64_t undecodable = 0, replaced = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait_for(lock, std::chrono::milliseconds(100),
                     [&] { return stop || !small_.empty() || !images_.empty(); });
      small.swap(small_);
      std::swap(undecodable, undecodable_);
      std::swap(replaced, replaced_);
      if (!images_.empty()) {
        auto oldest = images_.begin();
        for (auto it = images_.begin(); it != images_.end(); ++it)
          if (it->second.utime < oldest->second.utime) oldest = it;
        image = std::move(oldest->second);
        images_.erase(oldest);
      }
    }
    for (auto& apply : small) apply(core_);
    for (std::int64_t i = 0; i < undecodable; ++i) core_.onUndecodable();
    for (std::int64_t i = 0; i < replaced; ++i) core_.onReplaced();
    if (image) {
      if (const std::optional<NodeOutput> out = core_.onImage(*image)) {
        lcm_.publish(prefix_ + "HYPOTHESES", &out->hypotheses);
        if (publish_line_points_) lcm_.publish(prefix_ + "LINE_POINTS", &out->line_points);
      }
    }
    const localizer_status_t status = core_.status();
    if (SteadyClock::now() >= next_status || status.state != last_state_) {
      lcm_.publish(prefix_ + "STATUS", &status);
      last_state_ = status.state;
      next_status = SteadyClock::now() + std::chrono::seconds(1);
    }
  }
}

}  // namespace houghloc
