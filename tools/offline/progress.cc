#include "tools/offline/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace houghloc {
namespace {

constexpr int kBarWidth = 30;
constexpr double kTerminalPeriodS = 0.1;  // redraws per second are cheap but not free
constexpr double kLogPeriodS = 5.0;

double secondsBetween(std::chrono::steady_clock::time_point a,
                      std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

std::string formatDuration(double seconds) {
  const int s = static_cast<int>(seconds + 0.5);
  char text[32];
  if (s >= 3600) {
    std::snprintf(text, sizeof(text), "%dh%02dm", s / 3600, (s / 60) % 60);
  } else if (s >= 60) {
    std::snprintf(text, sizeof(text), "%dm%02ds", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof(text), "%ds", s);
  }
  return text;
}

}  // namespace

ProgressReporter::ProgressReporter(std::string label, int total, bool quiet)
    : label_(std::move(label)),
      total_(std::max(total, 0)),
      quiet_(quiet),
      terminal_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {}

std::string ProgressReporter::line(int done, double elapsed_s) const {
  const double fps = elapsed_s > 0.0 ? done / elapsed_s : 0.0;
  const double share = total_ > 0 ? static_cast<double>(done) / total_ : 1.0;
  const std::string eta = fps > 0.0 ? formatDuration((total_ - done) / fps) : "?";
  char text[160];
  if (terminal_) {
    const int filled = static_cast<int>(share * kBarWidth);
    const std::string bar =
        std::string(static_cast<size_t>(filled), '#') + std::string(kBarWidth - filled, '.');
    std::snprintf(text, sizeof(text), "%s [%s] %d/%d %3.0f%%  %.1f fps  ETA %s", label_.c_str(),
                  bar.c_str(), done, total_, 100.0 * share, fps, eta.c_str());
  } else {
    std::snprintf(text, sizeof(text), "%s: %d/%d frames (%.0f%%), %.1f fps, ETA %s", label_.c_str(),
                  done, total_, 100.0 * share, fps, eta.c_str());
  }
  return text;
}

void ProgressReporter::update(int done) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since_print = secondsBetween(last_print_, now);
  if (terminal_) {
    if (since_print < kTerminalPeriodS && done != total_) return;
    std::fprintf(stderr, "\r%s\033[K", line(done, secondsBetween(start_, now)).c_str());
    bar_open_ = true;
  } else {
    const int tenth = std::max(total_ / 10, 1);
    const bool step = done / tenth > last_printed_ / tenth || done == total_;
    if (!(step || since_print >= kLogPeriodS) || done == last_printed_) return;
    std::fprintf(stderr, "%s\n", line(done, secondsBetween(start_, now)).c_str());
    last_printed_ = done;
  }
  last_print_ = now;
  std::fflush(stderr);
}

void ProgressReporter::finish() {
  if (quiet_ || !bar_open_) return;
  std::fprintf(stderr, "\n");
  bar_open_ = false;
}

void ProgressReporter::warn(const std::string& message) {
  if (bar_open_) std::fprintf(stderr, "\r\033[K");
  std::fprintf(stderr, "warning: %s\n", message.c_str());
  bar_open_ = false;
  std::fflush(stderr);
}

}  // namespace houghloc
