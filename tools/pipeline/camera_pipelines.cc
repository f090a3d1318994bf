#include "tools/pipeline/camera_pipelines.h"

namespace houghloc {

VisionPipeline& CameraPipelines::forCamera(const std::string& id,
                                           const CameraIntrinsics& intrinsics) {
  std::unique_ptr<VisionPipeline>& pipeline = pipelines_[id];
  if (!pipeline) {
    pipeline = std::make_unique<VisionPipeline>(intrinsics, config_);
    if (field_) pipeline->setFieldModel(field_);
    if (config_.pose_correction.shared_between_cameras && first_) {
      pipeline->sharePoseCorrection(*first_);
    }
    if (!first_) first_ = pipeline.get();
  }
  return *pipeline;
}

const VisionPipeline* CameraPipelines::find(const std::string& id) const {
  const auto it = pipelines_.find(id);
  return it == pipelines_.end() ? nullptr : it->second.get();
}

}  // namespace houghloc
