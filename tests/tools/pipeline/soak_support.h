// Shared by the soak tests (LocalizationPipeline and houghloc-node over a whole match): what
// they measure (resident memory, CPU time) and rendered recordings looped into one long run.
#pragma once

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "tools/pipeline/localization_pipeline.h"
#include "tools/recording/recording.h"

namespace houghloc {

/// Resident set size of this process (MB), from /proc/self/statm.
inline double residentMegabytes() {
  std::ifstream statm("/proc/self/statm");
  long pages_total = 0, pages_resident = 0;
  statm >> pages_total >> pages_resident;
  return static_cast<double>(pages_resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1e6;
}

inline double cpuSeconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
/// CPU time of the calling thread (s).
inline double threadCpuSeconds() { return cpuSeconds(CLOCK_THREAD_CPUTIME_ID); }
/// CPU time of every thread of this process (s).
inline double processCpuSeconds() { return cpuSeconds(CLOCK_PROCESS_CPUTIME_ID); }

/// The median of `values` (0 when empty).
inline double medianOf(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

/// One step of a looped run: which recorded frame it replays, and the frame as the run sees it.
struct LoopedStep {
  std::size_t loop = 0;   ///< index into the loops given to LoopedRun
  std::size_t index = 0;  ///< frame index within that loop
  PipelineFrame frame;
};

/// Plays recorded loops back to back as one run: times continue (one frame period after the
/// loop's last frame), and odometry continues from where the previous loop ended (the robot is
/// carried to the loop's start pose, an unannounced kidnap to the localizer). Every frame must
/// have odometry and every loop at least two frames.
class LoopedRun {
 public:
  explicit LoopedRun(std::vector<std::vector<FrameRecord>> loops) : loops_(std::move(loops)) {
    for (const std::vector<FrameRecord>& loop : loops_) {
      if (loop.size() < 2) throw std::invalid_argument("LoopedRun: a loop needs two frames");
      for (const FrameRecord& f : loop) {
        if (!f.odometry) throw std::invalid_argument("LoopedRun: a frame without odometry");
      }
    }
  }

  /// Step n of the run (0, 1, 2, ... in order).
  LoopedStep step() {
    const std::size_t loop_index = loop_count_ % loops_.size();
    const std::vector<FrameRecord>& loop = loops_[loop_index];
    const FrameRecord& record = loop[frame_index_];
    const Pose2 start_inverse = loop.front().odometry->inverse();
    LoopedStep out;
    out.loop = loop_index;
    out.index = frame_index_;
    out.frame.t_us = t_offset_us_ + (record.t_us - loop.front().t_us);
    out.frame.camera_id = record.camera_id;
    out.frame.robot_T_camera = record.robot_T_camera;
    out.frame.odometry = odometry_offset_ * (start_inverse * *record.odometry);
    if (++frame_index_ == loop.size()) {
      frame_index_ = 0;
      ++loop_count_;
      t_offset_us_ = out.frame.t_us + (loop[1].t_us - loop[0].t_us);
      odometry_offset_ = *out.frame.odometry;
    }
    return out;
  }

 private:
  std::vector<std::vector<FrameRecord>> loops_;
  std::size_t loop_count_ = 0;
  std::size_t frame_index_ = 0;
  std::int64_t t_offset_us_ = 0;
  Pose2 odometry_offset_;
};

}  // namespace houghloc
