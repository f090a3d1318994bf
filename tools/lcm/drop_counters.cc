#include "tools/lcm/drop_counters.h"

namespace houghloc {

void DropCounters::add(DropReason reason) {
  switch (reason) {
    case DropReason::kOldImage:
      ++old_image;
      break;
    case DropReason::kNoCameraPose:
      ++no_camera_pose;
      break;
    case DropReason::kBadSize:
      ++bad_size;
      break;
    case DropReason::kMalformed:
      ++malformed;
      break;
    case DropReason::kQueueFull:
      ++queue_full;
      break;
  }
}

void DropCounters::fill(localizer_status_t& status) const {
  status.dropped_old_image = old_image;
  status.dropped_no_camera_pose = no_camera_pose;
  status.dropped_bad_size = bad_size;
  status.dropped_malformed = malformed;
  status.dropped_queue_full = queue_full;
}

const char* dropReasonName(DropReason reason) {
  switch (reason) {
    case DropReason::kOldImage:
      return "old image";
    case DropReason::kNoCameraPose:
      return "no camera pose";
    case DropReason::kBadSize:
      return "bad size";
    case DropReason::kMalformed:
      return "malformed message";
    case DropReason::kQueueFull:
      return "queue full";
  }
  return "unknown";
}

}  // namespace houghloc
