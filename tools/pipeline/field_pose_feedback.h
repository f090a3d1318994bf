#pragma once

#include <condition_variable>
#include <map>
#include <mutex>
#include <optional>

#include "field_models/pose2.h"
#include "localization/localizer.h"

namespace houghloc {

/// The localizer's track fed back to vision, where the pitch/roll corrector matches the line
/// points to the map at it (VisionPipeline::process's field_T_robot). Frame i gets the estimate
/// of frame i - lag_frames, predicted to frame i with odometry, so the result is the same
/// whether vision runs one frame ahead in its own thread or not (runVisionStage).
class FieldPoseFeedback {
 public:
  /// lag_frames >= 3 never waits with runVisionStage's two threads (the queue holds one frame).
  explicit FieldPoseFeedback(int first_frame, int lag_frames = 3);

  /// Consumer side, for every frame in order: the localizer's estimate of frame `index`
  /// (used while the tracker is tracking) and its cumulative odometry (DESIGN §3).
  void publish(int index, const std::optional<Pose2>& odometry,
               const LocalizationEstimate& estimate);
  /// Consumer side: frame `index` is done, published or not (e.g. a skipped image).
  void consumed(int index);
  /// Stops every wait (the run ends or failed).
  void abort();

  /// Vision side: where the localizer puts the robot at frame `index`, or none (not tracking,
  /// the first frames). Waits until frame index - lag_frames is consumed.
  std::optional<Pose2> guessFor(int index, const std::optional<Pose2>& odometry);

 private:
  struct Published {
    Pose2 field_T_robot;
    std::optional<Pose2> odometry;
  };

  int first_frame_;
  int lag_frames_;
  std::mutex mutex_;
  std::condition_variable changed_;
  int consumed_up_to_;  ///< every frame up to here is consumed
  bool aborted_ = false;
  std::map<int, Published> published_;
};

}  // namespace houghloc
