#pragma once

#include <chrono>
#include <string>

namespace houghloc {

/// Progress of a run on stderr. On a terminal: one redrawn bar with frames done/total, frames
/// per second and ETA. Otherwise (a log file, CI): a plain line with a newline every ~5 s or 10%
/// of the frames, so logs stay readable. Quiet: nothing.
class ProgressReporter {
 public:
  ProgressReporter(std::string label, int total, bool quiet);
  /// `done` frames finished (0..total).
  void update(int done);
  /// Ends the bar line (terminal) so later output starts on a fresh line.
  void finish();
  /// Prints a warning without breaking the bar (clears the line first on a terminal).
  void warn(const std::string& message);

 private:
  std::string line(int done, double elapsed_s) const;

  std::string label_;
  int total_ = 0;
  bool quiet_ = false;
  bool terminal_ = false;
  bool bar_open_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  int last_printed_ = 0;
};

}  // namespace houghloc
