#include "tools/play/play_schedule.h"

#include <algorithm>

namespace houghloc {
namespace {

// Order at equal times: what the node needs before an image comes first.
int rank(PlayEvent::Kind kind) {
  switch (kind) {
    case PlayEvent::Kind::kHint:
      return 0;
    case PlayEvent::Kind::kOdometry:
      return 1;
    case PlayEvent::Kind::kCameraPose:
      return 2;
    case PlayEvent::Kind::kImage:
      return 3;
    case PlayEvent::Kind::kGroundTruth:
      return 4;
  }
  return 5;
}

}  // namespace

std::vector<PlayEvent> buildSchedule(const Recording& recording, std::size_t num_hints) {
  std::vector<PlayEvent> events;
  for (std::size_t i = 0; i < recording.frames.size(); ++i) {
    const std::int64_t t = recording.frames[i].t_us;
    // A row without odometry publishes none: the node sees the silence a robot's source leaves.
    if (recording.frames[i].odometry) events.push_back({t, PlayEvent::Kind::kOdometry, i});
    events.push_back({t, PlayEvent::Kind::kCameraPose, i});
    events.push_back({t, PlayEvent::Kind::kImage, i});
  }
  for (std::size_t i = 0; i < num_hints && i < recording.hints.size(); ++i)
    events.push_back({recording.hints[i].t_us, PlayEvent::Kind::kHint, i});
  for (std::size_t i = 0; i < recording.ground_truth.size(); ++i)
    events.push_back({recording.ground_truth[i].t_us, PlayEvent::Kind::kGroundTruth, i});
  std::stable_sort(events.begin(), events.end(), [](const PlayEvent& a, const PlayEvent& b) {
    if (a.t_us != b.t_us) return a.t_us < b.t_us;
    return rank(a.kind) < rank(b.kind);
  });
  return events;
}

}  // namespace houghloc
