#pragma once

#include <cstdint>
#include <string>

#include "houghloc/localizer_status_t.hpp"

namespace houghloc {

/// Why an input was not used (DESIGN §7 localizer_status_t has one counter per reason).
enum class DropReason {
  kOldImage,      ///< older than the last processed image of the same camera
  kNoCameraPose,  ///< no camera pose within 50 ms of the image
  kBadSize,       ///< image size differs from its camera.yaml
  kMalformed,     ///< did not decode, wrong type, NaN or infinity, unknown format
  kQueueFull,     ///< replaced by a newer image of the same camera before it was processed
};

/// Counts of dropped inputs since start, per reason.
struct DropCounters {
  std::int64_t old_image = 0;
  std::int64_t no_camera_pose = 0;
  std::int64_t bad_size = 0;
  std::int64_t malformed = 0;
  std::int64_t queue_full = 0;

  void add(DropReason reason);
  std::int64_t total() const {
    return old_image + no_camera_pose + bad_size + malformed + queue_full;
  }
  /// Writes the five counters into a status message.
  void fill(localizer_status_t& status) const;
};

/// "old image", "no camera pose", ... for messages.
const char* dropReasonName(DropReason reason);

}  // namespace houghloc
