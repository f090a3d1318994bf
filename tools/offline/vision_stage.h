#pragma once

#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "tools/offline/field_pose_feedback.h"
#include "tools/offline/offline_context.h"
#include "vision/vision_pipeline.h"

namespace houghloc {

/// One frame after vision, as the localization modes consume it.
struct VisionFrame {
  int index = 0;  ///< into context.recording.frames
  const FrameRecord* frame = nullptr;
  const CameraIntrinsics* intrinsics = nullptr;
  bool skipped = false;          ///< image missing or unreadable
  std::string problem;           ///< why it was skipped
  std::optional<cv::Mat> image;  ///< kept only when overlays are drawn
  VisionResult result;           ///< empty points (t_us set) when skipped
  double load_ms = 0.0;          ///< reading and decoding the image
  double vision_ms = 0.0;        ///< VisionPipeline::process wall time
};

/// Runs vision over the context's frame range in order and hands each frame to `consume`, also
/// in order. threads == 2 runs vision (image decoding included) in a second thread, one frame
/// ahead of `consume`: every VisionPipeline still sees the frames in the same order and
/// `consume` is called with the same sequence, so the results equal the single-threaded run.
/// An exception from either side stops both and is rethrown here. With `feedback`, each frame's
/// vision gets the localizer's field pose from it (the pipelines get the context's field) and
/// every consumed frame is reported to it.
void runVisionStage(const OfflineContext& context, int threads, bool keep_images,
                    const std::function<void(VisionFrame&)>& consume,
                    FieldPoseFeedback* feedback = nullptr);

}  // namespace houghloc
