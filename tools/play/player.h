#pragma once

#include <atomic>
#include <cstdint>
#include <lcm/lcm-cpp.hpp>
#include <string>
#include <vector>

#include "localization/localization_hint.h"
#include "tools/play/play_schedule.h"
#include "tools/recording/recording.h"

namespace houghloc {

struct PlayOptions {
  std::string channel_prefix;  ///< prepended to IMAGE, ODOMETRY, CAMERA_POSE, HINT, GROUND_TRUTH
  double speed = 1.0;          ///< 2 = twice real time
  bool fast = false;           ///< next image when the previous one's HYPOTHESES arrived (1 s max)
  bool loop = false;
  std::int8_t pixel_format = 1;  ///< image_t::PIXEL_FORMAT_* (YUYV by default)
};

/// Publishes a recorded folder (DESIGN §5.1) on houghloc-node's input channels, re-stamped to
/// the clock of now: utime = CLOCK_MONOTONIC at the start of a pass + the recorded offset.
class Player {
 public:
  Player(lcm::LCM& lcm, const Recording& recording, const PlayOptions& options);
  /// One pass over the recording; returns the number of images published. Stops early when
  /// `stop` becomes true.
  int playOnce(const std::atomic<bool>& stop);
  /// HYPOTHESES messages seen while waiting in --fast mode.
  int hypothesesReceived() const { return hypotheses_received_; }

 private:
  void publish(const PlayEvent& event, std::int64_t utime);
  void waitForHypotheses(std::int64_t image_utime, const std::atomic<bool>& stop);

  lcm::LCM& lcm_;
  const Recording& recording_;
  PlayOptions options_;
  std::vector<LocalizationHint> hints_;
  std::vector<PlayEvent> schedule_;
  std::int64_t next_base_us_ = 0;  ///< a new pass starts after the previous one's last stamp
  std::int64_t last_hypotheses_utime_ = -1;
  int hypotheses_received_ = 0;
};

}  // namespace houghloc
