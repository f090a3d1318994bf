#include "tools/fieldmap/viewer_model/viewer_state.h"

#include <algorithm>
#include <cmath>
#include <lcm/lcm-cpp.hpp>
#include <stdexcept>

#include "tools/lcm/message_decoding.h"

namespace houghloc::fieldmap {
namespace {

bool finite(const pose_hypotheses_t& m) {
  for (const pose_hypothesis_t& h : m.hypotheses) {
    if (!std::isfinite(h.x) || !std::isfinite(h.y) || !std::isfinite(h.theta) ||
        !std::isfinite(h.weight))
      return false;
    for (double c : h.covariance)
      if (!std::isfinite(c)) return false;
  }
  return true;
}

bool finite(const line_points_t& m) {
  for (int i = 0; i < m.num_points; ++i)
    if (!std::isfinite(m.x[i]) || !std::isfinite(m.y[i])) return false;
  return true;
}

bool finite(const localizer_status_t& m) { return std::isfinite(m.cycle_time_ms); }

/// Decodes exactly `size` bytes (decodeMessage checks the type hash and every length).
template <typename T>
bool decodeInto(const void* bytes, int size, std::optional<T>& out) {
  T msg;
  if (size < 0 || !decodeMessage(bytes, static_cast<std::size_t>(size), msg) || !finite(msg))
    return false;
  out = std::move(msg);
  return true;
}

}  // namespace

ViewerState::ViewerState(std::vector<std::string> prefixes) : prefixes_(std::move(prefixes)) {
  if (prefixes_.empty()) prefixes_.push_back("");
  for (const std::string& p : prefixes_) robots_[p];
}

bool ViewerState::apply(const std::string& channel, const void* bytes, int size) {
  for (const std::string& prefix : prefixes_) {
    if (channel.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string name = channel.substr(prefix.size());
    RobotView& robot = robots_[prefix];
    bool ok = false;
    if (name == "HYPOTHESES") {
      ok = decodeInto(bytes, size, robot.hypotheses);
    } else if (name == "GROUND_TRUTH") {
      ok = decodeInto(bytes, size, robot.ground_truth);
    } else if (name == "LINE_POINTS") {
      ok = decodeInto(bytes, size, robot.points);
    } else if (name == "STATUS") {
      ok = decodeInto(bytes, size, robot.status);
    } else {
      continue;  // e.g. prefix "" and channel "NAO3_STATUS": try the longer prefixes
    }
    ok ? ++accepted_ : ++malformed_;
    return ok;
  }
  return false;
}

LogIndex::LogIndex(std::vector<LogMessage> messages) : messages_(std::move(messages)) {
  std::stable_sort(messages_.begin(), messages_.end(),
                   [](const LogMessage& a, const LogMessage& b) { return a.t_us < b.t_us; });
}

LogIndex::LogIndex(const std::string& path) {
  lcm::LogFile log(path, "r");
  if (!log.good()) throw std::runtime_error(path + ": cannot open the LCM log for reading");
  std::vector<LogMessage> messages;
  while (const lcm::LogEvent* e = log.readNextEvent()) {
    const auto* data = static_cast<const std::uint8_t*>(e->data);
    messages.push_back({e->timestamp, e->channel, {data, data + e->datalen}});
  }
  *this = LogIndex(std::move(messages));
}

ViewerState LogIndex::stateAt(std::int64_t t_us, const std::vector<std::string>& prefixes) const {
  ViewerState state(prefixes);
  for (const LogMessage& m : messages_) {
    if (m.t_us > t_us) break;
    state.apply(m.channel, m.data.data(), static_cast<int>(m.data.size()));
  }
  return state;
}

}  // namespace houghloc::fieldmap
