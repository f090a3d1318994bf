#include "tools/lcm/stop_signal.h"

#include <csignal>

namespace houghloc {
namespace {

std::atomic<bool> g_stop{false};
void onSignal(int) { g_stop = true; }

}  // namespace

const std::atomic<bool>& installStopSignals() {
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  return g_stop;
}

}  // namespace houghloc
