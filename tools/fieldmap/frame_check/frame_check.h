#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "field_models/field_model.h"
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
  /// With a map: the global localizer's poses for this frame alone, best first (on a
  /// point-symmetric field a pose and its mirror twin come together).
  std::vector<Pose2> located;
};

/// A recorded folder (DESIGN §5.1) for the check, run through LocalizationPipeline (the
/// recording's intrinsics, each frame alone: no track, no pitch/roll history).
class FrameSource {
 public:
  /// Throws RecordingError naming the file at fault.
  explicit FrameSource(const std::string& folder, const VisionConfig& config = {});

  int frameCount() const { return static_cast<int>(recording_.frames.size()); }
  const Recording& recording() const { return recording_; }
  /// Runs vision on frame `index` and, with `field`, the global localizer on its points (the
  /// map as edited now); throws RecordingError when the image cannot be read or the index is
  /// out of range.
  CheckFrame frame(int index, const FieldModel* field = nullptr);

 private:
  Recording recording_;
  VisionConfig config_;
};

}  // namespace houghloc::fieldmap
