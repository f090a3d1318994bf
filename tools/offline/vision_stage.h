#pragma once

#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "tools/offline/offline_context.h"
#include "tools/pipeline/localization_pipeline.h"

namespace houghloc {

/// One frame after vision, as the localization modes consume it.
struct VisionFrame {
  int index = 0;  ///< into context.recording.frames
  const FrameRecord* frame = nullptr;
  const CameraIntrinsics* intrinsics = nullptr;
  bool skipped = false;          ///< image missing or unreadable
  std::string problem;           ///< why it was skipped
  std::optional<cv::Mat> image;  ///< kept only when overlays are drawn
  SeenFrame seen;                ///< the pipeline's vision half (no points when skipped)
  double load_ms = 0.0;          ///< reading and decoding the image
  double vision_ms = 0.0;        ///< LocalizationPipeline::see wall time
};

/// Runs the pipeline's vision half (LocalizationPipeline::see, image loading included) over the
/// context's frame range in order and hands each frame to `consume`, also in order; `consume`
/// runs the localization half. threads == 2 runs vision in a second thread, one frame ahead of
/// `consume` (the pipeline's two-thread contract), so the results equal the single-threaded run.
/// An exception from either side stops both and is rethrown here.
void runVisionStage(const OfflineContext& context, LocalizationPipeline& pipeline, int threads,
                    bool keep_images, const std::function<void(VisionFrame&)>& consume);

/// The pipeline for a mode, with the context's configs, field and every camera of the frame
/// range (throws RecordingError for a camera without intrinsics); with --learn-tilt-first its
/// cameras' pitch/roll correctors have seen every frame of the range (learnCameraTilt).
std::unique_ptr<LocalizationPipeline> makePipeline(const OfflineContext& context,
                                                   PipelineMode mode);

/// Vision over the context's frame range in order, only to teach the pipeline's pitch/roll
/// correctors (LocalizationPipeline::learnCameraTilt); unreadable images are left out.
void learnCameraTilt(const OfflineContext& context, LocalizationPipeline& pipeline);

}  // namespace houghloc
