#include "tools/pipeline/field_pose_feedback.h"

#include <algorithm>

namespace houghloc {

FieldPoseFeedback::FieldPoseFeedback(int first_frame, int lag_frames)
    : first_frame_(first_frame),
      lag_frames_(std::max(1, lag_frames)),
      consumed_up_to_(first_frame - 1) {}

void FieldPoseFeedback::publish(int index, const std::optional<Pose2>& odometry,
                                const LocalizationEstimate& estimate) {
  const auto best = estimate.best();
  // Ambiguous on a symmetric field is fine: the mirrored pose fits the lines as well.
  const bool located =
      estimate.status == TrackerStatus::kTracking || estimate.status == TrackerStatus::kAmbiguous;
  if (!located || !best) return;
  std::lock_guard<std::mutex> lock(mutex_);
  published_[index] = {best->mean, odometry};
  // Older estimates are never asked for again.
  published_.erase(published_.begin(), published_.lower_bound(index - 2 * lag_frames_));
}

void FieldPoseFeedback::consumed(int index) {
  std::lock_guard<std::mutex> lock(mutex_);
  consumed_up_to_ = std::max(consumed_up_to_, index);
  changed_.notify_all();
}

void FieldPoseFeedback::abort() {
  std::lock_guard<std::mutex> lock(mutex_);
  aborted_ = true;
  changed_.notify_all();
}

std::optional<Pose2> FieldPoseFeedback::guessFor(int index, const std::optional<Pose2>& odometry) {
  const int source = index - lag_frames_;
  if (source < first_frame_) return std::nullopt;
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return aborted_ || consumed_up_to_ >= source; });
  const auto it = published_.find(source);
  if (aborted_ || it == published_.end()) return std::nullopt;
  const Published& then = it->second;
  // Odometry moved the robot by then^-1 * now since that frame, in the robot frame.
  if (then.odometry && then.odometry->isFinite() && odometry && odometry->isFinite()) {
    return then.field_T_robot * (then.odometry->inverse() * *odometry);
  }
  return then.field_T_robot;
}

}  // namespace houghloc
