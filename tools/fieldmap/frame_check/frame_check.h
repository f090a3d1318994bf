#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "field_models/pose2.h"
#include "tools/recording/recording.h"
#include "vision/vision_pipeline.h"

namespace houghloc::fieldmap {

/// One frame of a recorded folder prepared for the editor's check against reality: its line
/// points from the vision pipeline (robot frame) and the pose to start from.
struct CheckFrame {
  int index = 0;
  std::int64_t t_us = 0;
  std::vector<Eigen::Vector2d> points_robot;
  std::optional<Pose2> ground_truth;  ///< groundtruth.csv at the frame's time, if recorded
};

/// A recorded folder (DESIGN §5.1) for the check; the vision pipeline is houghloc-offline's
/// (CameraPipelines, the recording's intrinsics, no map feedback).
class FrameSource {
 public:
  /// Throws RecordingError naming the file at fault.
  explicit FrameSource(const std::string& folder, const VisionConfig& config = {});

  int frameCount() const { return static_cast<int>(recording_.frames.size()); }
  const Recording& recording() const { return recording_; }
  /// Runs vision on frame `index`; throws RecordingError when the image cannot be read or the
  /// index is out of range.
  CheckFrame frame(int index);

 private:
  Recording recording_;
  VisionConfig config_;
};

}  // namespace houghloc::fieldmap
