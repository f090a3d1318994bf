#include "tools/node/node_runner.h"

#include <chrono>
#include <cstdio>
#include <thread>

#include "tools/lcm/message_decoding.h"

namespace houghloc {
namespace {

using SteadyClock = std::chrono::steady_clock;

const char* stateName(std::int8_t state) {
  static const char* names[] = {"INITIALIZING", "TRACKING", "AMBIGUOUS", "LOST"};
  return state >= 0 && state < 4 ? names[state] : "?";
}

}  // namespace

NodeRunner::NodeRunner(lcm::LCM& lcm, NodeCore& core, const std::string& channel_prefix,
                       bool publish_line_points, const NodeRunnerOptions& options)
    : lcm_(lcm),
      core_(core),
      prefix_(channel_prefix),
      publish_line_points_(publish_line_points),
      options_(options) {
  auto small = [this](auto msg, void (NodeCore::*on)(const decltype(msg)&)) {
    return [this, on](const lcm::ReceiveBuffer& buf) {
      decltype(msg) m{};  // value-initialised: decode() fills it, the compiler cannot see that
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
    if (decode(buf, m)) submitImage(std::move(m));
  });
}

void NodeRunner::submitImage(image_t image) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto [it, inserted] = images_.try_emplace(image.camera_id);
  if (!inserted) ++replaced_;  // the newest image of a camera wins
  it->second = std::move(image);
  wake_.notify_one();
}

void NodeRunner::setCondition(const std::string& key, const std::string& text) {
  std::lock_guard<std::mutex> lock(mutex_);
  conditions_[key] = text;
  wake_.notify_one();
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
  // A last STATUS, so that subscribers (and a log's reader) see the final counters.
  publishStatus(core_.status());
  if (!options_.save_pose.empty()) savePose();
}

void NodeRunner::processLoop(const std::atomic<bool>& stop) {
  auto next_status = SteadyClock::now();
  const auto save_period = std::chrono::duration_cast<SteadyClock::duration>(
      std::chrono::duration<double>(options_.pose_file.save_period_s));
  auto next_save = SteadyClock::now() + save_period;
  while (!stop) {
    std::deque<std::function<void(NodeCore&)>> small;
    std::map<std::string, std::string> conditions;
    std::optional<image_t> image;
    std::int64_t undecodable = 0, replaced = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait_for(lock, std::chrono::milliseconds(100), [&] {
        return stop || !small_.empty() || !images_.empty() || !conditions_.empty();
      });
      small.swap(small_);
      conditions.swap(conditions_);
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
    for (const auto& [key, text] : conditions)
      text.empty() ? core_.clearCondition(key) : core_.setCondition(key, text);
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
    // A condition from another thread (a device) is news worth a STATUS at once.
    if (SteadyClock::now() >= next_status || status.state != last_state_ || !conditions.empty()) {
      publishStatus(status);
      next_status = SteadyClock::now() + std::chrono::seconds(1);
    }
    if (!options_.save_pose.empty() && SteadyClock::now() >= next_save) {
      savePose();
      next_save = SteadyClock::now() + save_period;
    }
  }
}

void NodeRunner::publishStatus(const localizer_status_t& status) {
  lcm_.publish(prefix_ + "STATUS", &status);
  if (NodeLog* log = options_.log) {
    if (status.state != last_state_)
      log->info(std::string("state ") + stateName(status.state) + " after " +
                std::to_string(status.frames_processed) + " images");
    if (status.message != last_message_ && !status.message.empty())
      log->warn("status: " + status.message);
    if (log->enabled(LogLevel::kDebug)) {
      char text[200];
      std::snprintf(text, sizeof(text),
                    "STATUS %s, %lld images, cycle %.2f ms, points %d/%d, dropped: old %lld, "
                    "no camera pose %lld, bad size %lld, malformed %lld, queue full %lld",
                    stateName(status.state), static_cast<long long>(status.frames_processed),
                    status.cycle_time_ms, status.points_used, status.points_in,
                    static_cast<long long>(status.dropped_old_image),
                    static_cast<long long>(status.dropped_no_camera_pose),
                    static_cast<long long>(status.dropped_bad_size),
                    static_cast<long long>(status.dropped_malformed),
                    static_cast<long long>(status.dropped_queue_full));
      log->debug(text);
    }
  }
  last_state_ = status.state;
  last_message_ = status.message;
}

void NodeRunner::savePose() {
  const LocalizationEstimate& estimate = core_.estimate();
  // A LOST or INITIALIZING estimate is not worth restoring: the file keeps the last good one.
  // AMBIGUOUS is saved: on a point-symmetric field without hints it is the steady state (the
  // twin comes back with every global injection), and its best is the one the node reports.
  if (estimate.status != TrackerStatus::kTracking && estimate.status != TrackerStatus::kAmbiguous)
    return;
  if (!estimate.best()) return;
  try {
    savePoseFile(options_.save_pose, *estimate.best());
  } catch (const std::exception& e) {
    if (options_.log) options_.log->warn(e.what());
  }
}

}  // namespace houghloc
