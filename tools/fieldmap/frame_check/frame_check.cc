#include "tools/fieldmap/frame_check/frame_check.h"

#include <opencv2/imgcodecs.hpp>

#include "tools/offline/camera_pipelines.h"

namespace houghloc::fieldmap {

FrameSource::FrameSource(const std::string& folder, const VisionConfig& config)
    : recording_(readRecording(folder)), config_(config) {}

CheckFrame FrameSource::frame(int index) {
  if (index < 0 || index >= frameCount()) {
    throw RecordingError(recording_.folder + "/frames.csv: no frame " + std::to_string(index) +
                         " (the folder has " + std::to_string(frameCount()) + ")");
  }
  const FrameRecord& record = recording_.frames[index];
  const std::string path = recording_.folder + "/" + record.image;
  const cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty()) throw RecordingError(path + ": cannot read the image");
  // A fresh pipeline per frame: a single frame has no history for the pitch/roll corrector.
  CameraPipelines pipelines(config_, nullptr);
  const VisionResult result =
      pipelines.forFrame(recording_, record).process(image, record.robot_T_camera, record.t_us);
  CheckFrame out;
  out.index = index;
  out.t_us = record.t_us;
  for (const GroundPoint& p : result.ground.points) out.points_robot.push_back(p.p_robot);
  out.ground_truth = groundTruthAt(recording_.ground_truth, record.t_us);
  return out;
}

}  // namespace houghloc::fieldmap
