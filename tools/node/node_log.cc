#include "tools/node/node_log.h"

namespace houghloc {
namespace {

constexpr const char* kNames[] = {"error", "warn", "info", "debug"};

}  // namespace

std::optional<LogLevel> parseLogLevel(const std::string& name) {
  for (int i = 0; i < 4; ++i)
    if (name == kNames[i]) return static_cast<LogLevel>(i);
  return std::nullopt;
}

const char* logLevelName(LogLevel level) { return kNames[static_cast<int>(level)]; }

void NodeLog::write(LogLevel level, const std::string& text) {
  if (!enabled(level)) return;
  std::lock_guard<std::mutex> lock(mutex_);
  *out_ << "houghloc-node: " << logLevelName(level) << ": " << text << "\n" << std::flush;
}

}  // namespace houghloc
