#include "tools/pipeline/localization_pipeline.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "localization/global_hough_localizer.h"

namespace houghloc {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// Only the full mode feeds the track back, so only its correctors get the map.
std::shared_ptr<const FieldModel> correctorMap(PipelineMode mode,
                                               const std::shared_ptr<const FieldModel>& field) {
  return mode == PipelineMode::kFull ? field : nullptr;
}

/// The vision's line width and centre-circle radius come from the map when there is one, so a
/// field with other dimensions than the defaults needs no config file (every tool alike).
PipelineConfig withFieldDimensions(PipelineConfig config, const FieldModel* field) {
  if (!field) return config;
  config.vision.line_width_m = field->line_width;
  for (const Arc2& arc : field->arcs) {
    if (arc.isFullCircle() && arc.center.norm() < 1e-6) {
      config.vision.segments.circle_radius_m = arc.radius;
    }
  }
  return config;
}

}  // namespace

LocalizationPipeline::LocalizationPipeline(PipelineMode mode,
                                           std::shared_ptr<const FieldModel> field,
                                           const PipelineConfig& config)
    : mode_(mode),
      config_(withFieldDimensions(config, field.get())),
      field_(std::move(field)),
      cameras_(config_.vision, correctorMap(mode, field_)),
      feedback_(0, config.track_feedback_lag_frames) {
  if (!field_ && mode_ != PipelineMode::kVisionOnly) {
    throw std::invalid_argument("LocalizationPipeline: localization needs a field map");
  }
  if (mode_ == PipelineMode::kFull) localizer_.emplace(*field_, config_.localizer);
  if (mode_ == PipelineMode::kGlobalOnly) {
    global_ = std::make_unique<const GlobalHoughLocalizer>(*field_, config_.localizer.global);
  }
}

LocalizationPipeline::~LocalizationPipeline() = default;

void LocalizationPipeline::setCamera(const std::string& id, const CameraIntrinsics& intrinsics) {
  intrinsics_[id] = intrinsics;
}

VisionPipeline& LocalizationPipeline::visionFor(const std::string& camera_id) {
  const auto intrinsics = intrinsics_.find(camera_id);
  if (intrinsics == intrinsics_.end()) {
    throw std::invalid_argument("no intrinsics for camera '" + camera_id + "'");
  }
  return cameras_.forCamera(camera_id, intrinsics->second);
}

SeenFrame LocalizationPipeline::see(const PipelineFrame& frame, const cv::Mat& image) {
  VisionPipeline& vision = visionFor(frame.camera_id);
  std::optional<Pose2> field_T_robot;
  if (mode_ == PipelineMode::kFull)
    field_T_robot = feedback_.guessFor(next_sequence_, frame.odometry);
  SeenFrame seen;
  seen.vision = vision.process(image, frame.robot_T_camera, frame.t_us, field_T_robot);
  seen.frame = frame;
  seen.has_image = true;
  seen.sequence = next_sequence_++;
  return seen;
}

void LocalizationPipeline::learnCameraTilt(const PipelineFrame& frame, const cv::Mat& image) {
  // Without a field pose: the corrector learns from the lines' geometry alone.
  visionFor(frame.camera_id).process(image, frame.robot_T_camera, frame.t_us, std::nullopt);
}

SeenFrame LocalizationPipeline::seeNothing(const PipelineFrame& frame) {
  SeenFrame seen;
  seen.frame = frame;
  seen.vision.ground.t_us = frame.t_us;
  seen.sequence = next_sequence_++;
  return seen;
}

PipelineResult LocalizationPipeline::locate(const SeenFrame& seen) {
  PipelineResult result;
  const auto start = Clock::now();
  if (mode_ == PipelineMode::kFull) {
    // Hints take effect at their time: all of those up to this frame's time, in order.
    while (!hints_.empty() && hints_.front().t_us <= seen.frame.t_us) {
      localizer_->applyHint(hints_.front());
      hints_.pop_front();
    }
    result.estimate = localizer_->process(seen.frame.t_us, seen.frame.odometry,
                                          {seen.frame.robot_T_camera}, seen.vision.ground);
    result.global_ms = result.estimate.global_ms;
    result.global_ran = result.estimate.global_ran;
    feedback_.publish(seen.sequence, seen.frame.odometry, result.estimate);
  } else if (mode_ == PipelineMode::kGlobalOnly) {
    result.global = global_->locate(seen.vision.ground);
    result.global_ms = msSince(start);
    result.global_ran = true;
  }
  result.localization_ms = msSince(start);
  feedback_.consumed(seen.sequence);
  return result;
}

void LocalizationPipeline::queueHint(const LocalizationHint& hint) {
  // After every queued hint of the same or an earlier time: hints of one time keep their order.
  const auto later = std::upper_bound(
      hints_.begin(), hints_.end(), hint.t_us,
      [](std::int64_t t_us, const LocalizationHint& queued) { return t_us < queued.t_us; });
  hints_.insert(later, hint);
}

LocalizationEstimate LocalizationPipeline::estimate() const {
  return localizer_ ? localizer_->estimate() : LocalizationEstimate{};
}

}  // namespace houghloc
