#include "tools/fieldmap/viewer_model/lcm_feed.h"

#include <stdexcept>

namespace houghloc::fieldmap {

LcmFeed::LcmFeed(const std::string& url, ViewerState* state) : lcm_(url), state_(state) {
  if (!lcm_.good()) throw std::runtime_error("cannot start LCM on '" + url + "'");
  lcm_.subscribe(".*", &LcmFeed::onMessage, this);
}

void LcmFeed::onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  if (state_->apply(channel, buffer->data, static_cast<int>(buffer->data_size))) ++accepted_;
}

int LcmFeed::poll() {
  accepted_ = 0;
  // handleTimeout(0) returns > 0 while a message was handled, 0 when none is waiting.
  while (lcm_.handleTimeout(0) > 0) {
  }
  return accepted_;
}

}  // namespace houghloc::fieldmap
