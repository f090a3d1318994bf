#include "tools/fieldmap/frame_check/frame_check.h"

#include <opencv2/imgcodecs.hpp>

#include "localization/pose_hypothesis.h"
#include "tools/pipeline/localization_pipeline.h"

namespace houghloc::fieldmap {

FrameSource::FrameSource(const std::string& folder, const VisionConfig& config)
    : recording_(readRecording(folder)), config_(config) {}

CheckFrame FrameSource::frame(int index, const FieldModel* field) {
  if (index < 0 || index >= frameCount()) {
    throw RecordingError(recording_.folder + "/frames.csv: no frame " + std::to_string(index) +
                         " (the folder has " + std::to_string(frameCount()) + ")");
  }
  const FrameRecord& record = recording_.frames[index];
  const std::string path = recording_.folder + "/" + record.image;
  const cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty()) throw RecordingError(path + ": cannot read the image");
  // A fresh pipeline per frame: a single frame has no history for the pitch/roll corrector.
  PipelineConfig config;
  config.vision = config_;
  LocalizationPipeline pipeline(field ? PipelineMode::kGlobalOnly : PipelineMode::kVisionOnly,
                                field ? std::make_shared<const FieldModel>(*field) : nullptr,
                                config);
  pipeline.setCamera(record.camera_id, recording_.intrinsicsFor(record));
  const SeenFrame seen =
      pipeline.see({record.t_us, record.camera_id, record.robot_T_camera, record.odometry}, image);
  const PipelineResult located = pipeline.locate(seen);
  const VisionResult& result = seen.vision;
  CheckFrame out;
  out.index = index;
  out.t_us = record.t_us;
  for (const GroundPoint& p : result.ground.points) out.points_robot.push_back(p.p_robot);
  out.ground_truth = groundTruthAt(recording_.ground_truth, record.t_us);
  for (const PoseHypothesis& h : located.global) {
    if (h.kind != HypothesisKind::kHeadingOnly) out.located.push_back(h.field_T_robot);
  }
  return out;
}

}  // namespace houghloc::fieldmap
