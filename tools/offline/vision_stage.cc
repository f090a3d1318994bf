#include "tools/offline/vision_stage.h"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "tools/offline/offline_output.h"
#include "tools/offline/progress.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

PipelineFrame pipelineFrame(const FrameRecord& frame) {
  return {frame.t_us, frame.camera_id, frame.robot_T_camera, frame.odometry};
}

/// A frame the pipeline refused (wrong size or type, a non-finite pose), named by its file.
std::runtime_error frameError(const Recording& rec, const FrameRecord& frame,
                              const std::invalid_argument& e) {
  return std::runtime_error((fs::path(rec.folder) / frame.image).string() + ": " + e.what());
}

/// Image loading and the pipeline's vision half, fed strictly in frame order.
class VisionWorker {
 public:
  VisionWorker(const OfflineContext& context, LocalizationPipeline& pipeline, bool keep_images)
      : context_(context), pipeline_(pipeline), keep_images_(keep_images) {}

  VisionFrame process(int index) {
    const Recording& rec = context_.recording;
    VisionFrame out;
    out.index = index;
    out.frame = &rec.frames[static_cast<size_t>(index)];
    out.intrinsics = &rec.intrinsicsFor(*out.frame);
    const auto load_start = Clock::now();
    std::optional<cv::Mat> image = loadFrameImage(context_, *out.frame, &out.problem);
    out.load_ms = msSince(load_start);
    if (!image) {
      out.skipped = true;
      out.seen = pipeline_.seeNothing(pipelineFrame(*out.frame));
      return out;
    }
    const auto start = Clock::now();
    try {
      out.seen = pipeline_.see(pipelineFrame(*out.frame), *image);
    } catch (const std::invalid_argument& e) {
      throw frameError(rec, *out.frame, e);
    }
    out.vision_ms = msSince(start);
    if (keep_images_) out.image = std::move(image);
    return out;
  }

 private:
  const OfflineContext& context_;
  LocalizationPipeline& pipeline_;
  bool keep_images_;
};

/// A bounded hand-over queue between the vision thread and the consumer.
class FrameQueue {
 public:
  explicit FrameQueue(size_t capacity) : capacity_(capacity) {}

  /// False when the consumer has stopped.
  bool push(VisionFrame frame) {
    std::unique_lock<std::mutex> lock(mutex_);
    space_.wait(lock, [&] { return frames_.size() < capacity_ || stopped_; });
    if (stopped_) return false;
    frames_.push_back(std::move(frame));
    ready_.notify_one();
    return true;
  }
  /// False when the producer finished (or failed: then `error` is set) and nothing is left.
  bool pop(VisionFrame* frame) {
    std::unique_lock<std::mutex> lock(mutex_);
    ready_.wait(lock, [&] { return !frames_.empty() || done_; });
    if (frames_.empty()) return false;
    *frame = std::move(frames_.front());
    frames_.pop_front();
    space_.notify_one();
    return true;
  }
  void finish(std::exception_ptr error) {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
    error_ = error;
    ready_.notify_all();
  }
  void stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    space_.notify_all();
  }
  std::exception_ptr error() {
    std::lock_guard<std::mutex> lock(mutex_);
    return error_;
  }

 private:
  size_t capacity_;
  std::mutex mutex_;
  std::condition_variable ready_, space_;
  std::deque<VisionFrame> frames_;
  bool done_ = false, stopped_ = false;
  std::exception_ptr error_;
};

}  // namespace

std::unique_ptr<LocalizationPipeline> makePipeline(const OfflineContext& context,
                                                   PipelineMode mode) {
  PipelineConfig config;
  config.vision = context.vision_config;
  config.localizer = context.localizer_config;
  std::shared_ptr<const FieldModel> field;
  if (context.field) field = std::make_shared<const FieldModel>(*context.field);
  auto pipeline = std::make_unique<LocalizationPipeline>(mode, field, config);
  const Recording& rec = context.recording;
  for (int i = context.first_frame; i < context.end_frame; ++i) {
    const FrameRecord& frame = rec.frames[static_cast<size_t>(i)];
    pipeline->setCamera(frame.camera_id, rec.intrinsicsFor(frame));
  }
  for (const LocalizationHint& hint : context.hints) pipeline->queueHint(hint);
  if (context.options.learn_tilt_first) learnCameraTilt(context, *pipeline);
  return pipeline;
}

void learnCameraTilt(const OfflineContext& context, LocalizationPipeline& pipeline) {
  ProgressReporter progress("learning the camera tilt", context.end_frame - context.first_frame,
                            context.options.quiet);
  for (int i = context.first_frame; i < context.end_frame; ++i) {
    const FrameRecord& frame = context.recording.frames[static_cast<size_t>(i)];
    std::string problem;  // reported by the run itself
    if (const std::optional<cv::Mat> image = loadFrameImage(context, frame, &problem)) {
      try {
        pipeline.learnCameraTilt(pipelineFrame(frame), *image);
      } catch (const std::invalid_argument& e) {
        throw frameError(context.recording, frame, e);
      }
    }
    progress.update(i + 1 - context.first_frame);
  }
  progress.finish();
}

void runVisionStage(const OfflineContext& context, LocalizationPipeline& pipeline, int threads,
                    bool keep_images, const std::function<void(VisionFrame&)>& consume) {
  VisionWorker worker(context, pipeline, keep_images);
  if (threads <= 1) {
    for (int i = context.first_frame; i < context.end_frame; ++i) {
      VisionFrame frame = worker.process(i);
      consume(frame);
    }
    return;
  }
  // One frame in the queue plus the one being processed keeps both threads busy.
  FrameQueue queue(1);
  std::thread producer([&] {
    std::exception_ptr error;
    try {
      for (int i = context.first_frame; i < context.end_frame; ++i) {
        if (!queue.push(worker.process(i))) break;
      }
    } catch (...) {
      error = std::current_exception();
    }
    queue.finish(error);
  });
  try {
    VisionFrame frame;
    while (queue.pop(&frame)) consume(frame);
  } catch (...) {
    queue.stop();
    pipeline.stop();  // the producer may wait for a frame never located
    producer.join();
    throw;
  }
  producer.join();
  if (std::exception_ptr error = queue.error()) std::rethrow_exception(error);
}

}  // namespace houghloc
