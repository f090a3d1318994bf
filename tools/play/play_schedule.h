#pragma once

#include <cstdint>
#include <vector>

#include "tools/recording/recording.h"

namespace houghloc {

/// What houghloc-play publishes at one recorded time.
struct PlayEvent {
  enum class Kind { kOdometry, kCameraPose, kImage, kHint, kGroundTruth };
  std::int64_t t_us = 0;  ///< recorded time
  Kind kind = Kind::kImage;
  std::size_t index = 0;  ///< into frames, hints (convertHints order) or ground_truth
};

/// Every message of a recorded folder in publication order: by recorded time; at equal times
/// odometry and camera pose before the image (so the node has them when the image arrives),
/// hints before the frame they precede, ground truth last. A frame without odometry (empty
/// odom_* fields) has no odometry event.
std::vector<PlayEvent> buildSchedule(const Recording& recording, std::size_t num_hints);

}  // namespace houghloc
