#pragma once

#include <lcm/lcm-cpp.hpp>
#include <string>

#include "tools/fieldmap/viewer_model/viewer_state.h"

namespace houghloc::fieldmap {

/// Feeds a ViewerState from an LCM bus (udpm://, memq://, file://): subscribes to every channel
/// and lets ViewerState pick its prefixes' messages. Single-threaded: poll() from the GUI loop.
class LcmFeed {
 public:
  /// Throws std::runtime_error naming `url` when LCM cannot start on it.
  LcmFeed(const std::string& url, ViewerState* state);

  /// Handles every message waiting now (never blocks); returns how many the state accepted.
  int poll();
  lcm::LCM& lcm() { return lcm_; }

 private:
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel);

  lcm::LCM lcm_;
  ViewerState* state_;
  int accepted_ = 0;
};

}  // namespace houghloc::fieldmap
