#pragma once

#include <map>
#include <memory>
#include <string>

#include "field_models/field_model.h"
#include "vision/camera_model.h"
#include "vision/vision_pipeline.h"

namespace houghloc {

/// One VisionPipeline per camera id, created at the camera's first frame: each gets the map for
/// the pitch/roll corrector (when given), and with `pose_correction.shared_between_cameras` all
/// share the first camera's corrector (an error the cameras share, e.g. a head joint offset).
class CameraPipelines {
 public:
  /// field: the map the correctors match points against in frames with a field pose; null:
  /// no map residuals.
  CameraPipelines(const VisionConfig& config, std::shared_ptr<const FieldModel> field)
      : config_(config), field_(std::move(field)) {}

  /// The pipeline of camera `id`; created with `intrinsics` when the camera is new (later calls
  /// keep the first intrinsics).
  VisionPipeline& forCamera(const std::string& id, const CameraIntrinsics& intrinsics);

  /// The camera's pipeline, or null before its first frame.
  const VisionPipeline* find(const std::string& id) const;

 private:
  VisionConfig config_;
  std::shared_ptr<const FieldModel> field_;
  std::map<std::string, std::unique_ptr<VisionPipeline>> pipelines_;
  const VisionPipeline* first_ = nullptr;  ///< whose corrector the others may share
};

}  // namespace houghloc
