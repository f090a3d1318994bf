#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "field_models/field_model.h"
#include "localization/localization_hint.h"
#include "localization/localizer.h"
#include "localization/pose_hypothesis.h"
#include "tools/pipeline/camera_pipelines.h"
#include "tools/pipeline/field_pose_feedback.h"
#include "vision/vision_pipeline.h"

namespace houghloc {

class GlobalHoughLocalizer;

/// What runs per frame (DESIGN §5.2's modes; the onboard node runs kFull).
enum class PipelineMode {
  kFull,        ///< vision, then the Localizer facade (tracking, hints); its track goes back
                ///< to vision's pitch/roll corrector
  kGlobalOnly,  ///< vision, then GlobalHoughLocalizer::locate() on every frame alone
  kVisionOnly,  ///< vision alone
};

struct PipelineConfig {
  VisionConfig vision;
  LocalizerConfig localizer;
  /// kFull: vision of frame n gets the localizer's estimate of frame n - this, moved to frame n
  /// by odometry, for the corrector's map matching. 3 lets vision run one frame ahead of
  /// localization in another thread without ever waiting (see LocalizationPipeline).
  int track_feedback_lag_frames = 3;
};

/// One camera frame as every tool hands it over (from a recorded folder or from LCM).
struct PipelineFrame {
  std::int64_t t_us = 0;
  std::string camera_id;          ///< "" = the only camera
  Pose3 robot_T_camera;           ///< recorded camera pose at the image's time
  std::optional<Pose2> odometry;  ///< cumulative odometry at the image's time (DESIGN §3)
};

/// A frame after the vision half of the step.
struct SeenFrame {
  PipelineFrame frame;
  int sequence = 0;  ///< 0, 1, 2, ... in the order see() / seeNothing() were called
  bool has_image = false;
  VisionResult vision;  ///< without an image: no points, t_us set
};

/// A frame after the localization half.
struct PipelineResult {
  LocalizationEstimate estimate;       ///< kFull: the Localizer's estimate
  std::vector<PoseHypothesis> global;  ///< kGlobalOnly: locate()'s hypotheses, best first
  double localization_ms = 0.0;        ///< wall time of the whole localization half
  double global_ms = 0.0;              ///< of which the global localizer
  bool global_ran = false;
};

/// The one composition of vision and localization that every tool runs (houghloc-offline's
/// three modes, houghloc-node, the field-map editor's check against a frame): one
/// VisionPipeline per camera id (CameraPipelines: a shared pitch/roll corrector when
/// configured), the Localizer facade with hints, and the localizer's track fed back to the
/// correctors (FieldPoseFeedback). Knows no files, LCM or printing.
///
/// A step is see() (or seeNothing() for a frame without a usable image) then locate(), or
/// process() for both. Threading: see() and locate() touch disjoint state and may run on two
/// threads, each called in frame order, see() at most track_feedback_lag_frames - 1 frames
/// ahead of locate() (see() of frame n waits until locate() of frame n - lag is done; stop()
/// ends such a wait). Everything else: one caller at a time. The results are the same whether
/// the halves run on one thread or two.
class LocalizationPipeline {
 public:
  /// field: required for kFull and kGlobalOnly (std::invalid_argument otherwise), may be null
  /// for kVisionOnly. Builds the map data once (tens of ms).
  LocalizationPipeline(PipelineMode mode, std::shared_ptr<const FieldModel> field,
                       const PipelineConfig& config);
  ~LocalizationPipeline();

  /// Intrinsics of camera `id`, before its first frame (a camera without them is an error).
  void setCamera(const std::string& id, const CameraIntrinsics& intrinsics);

  /// The vision half: image (BGR8 CV_8UC3 or YUYV CV_8UC2 of the camera's size) to ground
  /// points. Throws std::invalid_argument for an unknown camera, a wrong image size or type and
  /// a non-finite camera pose (the frame then counts as never seen).
  SeenFrame see(const PipelineFrame& frame, const cv::Mat& image);
  /// The vision half of a frame whose image is missing or unreadable: no points, so the
  /// localization half only predicts with odometry.
  SeenFrame seeNothing(const PipelineFrame& frame);
  /// The localization half, for the frames of see() / seeNothing() in their order. Hints queued
  /// with queueHint() and due by the frame's time are applied first (kFull).
  PipelineResult locate(const SeenFrame& seen);
  /// Both halves on the calling thread.
  PipelineResult process(const PipelineFrame& frame, const cv::Mat& image) {
    return locate(see(frame, image));
  }

  /// Vision alone on one frame, only to teach its camera's pitch/roll corrector (no sequence
  /// number, no localization; the field colour memory moves on as in see()). Run over a whole
  /// folder before the run, every frame then starts from what all of them say about the
  /// camera's tilt: a folder of stills from one robot, or a recording whose recorded camera
  /// pose is off from its first frame. Throws like see().
  void learnCameraTilt(const PipelineFrame& frame, const cv::Mat& image);

  /// A hint takes effect before the first frame whose t_us is at or after the hint's (hints
  /// with the same time in the order queued). Ignored by kGlobalOnly and kVisionOnly.
  void queueHint(const LocalizationHint& hint);
  /// The Localizer's current estimate (kFull; empty otherwise).
  LocalizationEstimate estimate() const;

  /// Wakes a see() waiting for the track in another thread, for good: the run ends or failed.
  void stop() { feedback_.abort(); }

  PipelineMode mode() const { return mode_; }
  /// The camera's vision pipeline (its corrector's state), or null before its first frame.
  const VisionPipeline* camera(const std::string& id) const { return cameras_.find(id); }

 private:
  /// The camera's vision pipeline, made at its first frame; throws for a camera without
  /// intrinsics.
  VisionPipeline& visionFor(const std::string& camera_id);

  PipelineMode mode_;
  PipelineConfig config_;
  std::shared_ptr<const FieldModel> field_;
  std::map<std::string, CameraIntrinsics> intrinsics_;
  CameraPipelines cameras_;
  FieldPoseFeedback feedback_;
  int next_sequence_ = 0;
  std::optional<Localizer> localizer_;                  ///< kFull
  std::unique_ptr<const GlobalHoughLocalizer> global_;  ///< kGlobalOnly
  std::deque<LocalizationHint> hints_;                  ///< queued, in time order
};

}  // namespace houghloc
