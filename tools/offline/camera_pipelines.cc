#include "tools/offline/camera_pipelines.h"

namespace houghloc {

VisionPipeline& CameraPipelines::forFrame(const Recording& recording, const FrameRecord& frame) {
  std::unique_ptr<VisionPipeline>& pipeline = pipelines_[frame.camera_id];
  if (!pipeline) {
    pipeline = std::make_unique<VisionPipeline>(recording.intrinsicsFor(frame), config_);
    if (field_) pipeline->setFieldModel(field_);
    if (config_.pose_correction.shared_between_cameras && first_) {
      pipeline->sharePoseCorrection(*first_);
    }
    if (!first_) first_ = pipeline.get();
  }
  return *pipeline;
}

}  // namespace houghloc
