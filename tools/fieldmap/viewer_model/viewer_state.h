#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "houghloc/line_points_t.hpp"
#include "houghloc/localizer_status_t.hpp"
#include "houghloc/pose_hypotheses_t.hpp"

namespace houghloc::fieldmap {

/// What the viewer knows of one robot (one channel prefix): the newest message of each kind.
struct RobotView {
  std::optional<pose_hypotheses_t> hypotheses;    ///< <P>HYPOTHESES, sorted best first
  std::optional<line_points_t> points;            ///< <P>LINE_POINTS (robot frame)
  std::optional<localizer_status_t> status;       ///< <P>STATUS
  std::optional<pose_hypotheses_t> ground_truth;  ///< <P>GROUND_TRUTH (one hypothesis)
};

/// The live viewer's model (DESIGN §7 channels), free of LCM transport and Qt: fed raw message
/// bytes per channel, it keeps the newest message of each kind for every subscribed prefix.
class ViewerState {
 public:
  explicit ViewerState(std::vector<std::string> prefixes);

  /// Decodes `bytes` if `channel` is <P>HYPOTHESES, LINE_POINTS, STATUS or GROUND_TRUTH of a
  /// subscribed prefix. Returns false (state unchanged) for other channels and for bytes that
  /// do not decode or carry non-finite numbers.
  bool apply(const std::string& channel, const void* bytes, int size);

  const std::vector<std::string>& prefixes() const { return prefixes_; }
  const RobotView& robot(const std::string& prefix) const { return robots_.at(prefix); }
  /// Messages accepted and refused (malformed) since construction.
  int accepted() const { return accepted_; }
  int malformed() const { return malformed_; }
  bool empty() const { return accepted_ == 0; }

 private:
  std::vector<std::string> prefixes_;
  std::map<std::string, RobotView> robots_;
  int accepted_ = 0;
  int malformed_ = 0;
};

/// One LCM event of a log (an lcm-logger file).
struct LogMessage {
  std::int64_t t_us = 0;  ///< the logger's receive time, microseconds
  std::string channel;
  std::vector<std::uint8_t> data;
};

/// All events of a log, sorted by time, for the viewer's time slider: the state at time t is the
/// replay of every event up to and including t.
class LogIndex {
 public:
  /// Reads every event of `path`; throws std::runtime_error naming the file when it cannot be
  /// opened.
  explicit LogIndex(const std::string& path);
  explicit LogIndex(std::vector<LogMessage> messages);

  const std::vector<LogMessage>& messages() const { return messages_; }
  std::int64_t startUs() const { return messages_.empty() ? 0 : messages_.front().t_us; }
  std::int64_t endUs() const { return messages_.empty() ? 0 : messages_.back().t_us; }
  /// Replays the events with t_us <= t into a fresh state for `prefixes`.
  ViewerState stateAt(std::int64_t t_us, const std::vector<std::string>& prefixes) const;

 private:
  std::vector<LogMessage> messages_;
};

}  // namespace houghloc::fieldmap
