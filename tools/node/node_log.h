#pragma once

#include <mutex>
#include <optional>
#include <ostream>
#include <string>

namespace houghloc {

/// How much houghloc-node prints (--log-level), least to most.
enum class LogLevel {
  kError,  ///< only what stops the node
  kWarn,   ///< + problems it works around: a missing device, streams apart, a restart
  kInfo,   ///< + start, state changes, a restored pose, the summary at exit
  kDebug,  ///< + every STATUS and every retry
};

/// "error", "warn", "info", "debug" to LogLevel; none for anything else.
std::optional<LogLevel> parseLogLevel(const std::string& name);
const char* logLevelName(LogLevel level);

/// The node's printing, one line per call ("houghloc-node: warn: ..."), from any thread. Only
/// tools print (DESIGN §2): NodeCore and the libraries report through the status message.
class NodeLog {
 public:
  explicit NodeLog(LogLevel level, std::ostream& out) : level_(level), out_(&out) {}

  bool enabled(LogLevel level) const { return level <= level_; }
  void write(LogLevel level, const std::string& text);
  void error(const std::string& text) { write(LogLevel::kError, text); }
  void warn(const std::string& text) { write(LogLevel::kWarn, text); }
  void info(const std::string& text) { write(LogLevel::kInfo, text); }
  void debug(const std::string& text) { write(LogLevel::kDebug, text); }

 private:
  LogLevel level_;
  std::ostream* out_;
  std::mutex mutex_;
};

}  // namespace houghloc
