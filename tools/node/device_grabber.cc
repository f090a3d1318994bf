#include "tools/node/device_grabber.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <opencv2/videoio.hpp>

#include "tools/lcm/clock.h"

namespace houghloc {

DeviceGrabber::DeviceGrabber(std::string camera_id, std::string device, int width, int height,
                             std::function<void(image_t)> on_image,
                             std::function<void(const std::string&)> on_problem, NodeLog* log,
                             const DeviceGrabberConfig& config)
    : camera_id_(std::move(camera_id)),
      device_(std::move(device)),
      width_(width),
      height_(height),
      on_image_(std::move(on_image)),
      on_problem_(std::move(on_problem)),
      log_(log),
      config_(config) {}

void DeviceGrabber::start() {
  thread_ = std::thread([this] { loop(); });
}

void DeviceGrabber::requestStop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
}

void DeviceGrabber::stop() {
  requestStop();
  if (thread_.joinable()) thread_.join();
}

void DeviceGrabber::loop() {
  grabUntilStopped();
  finished_ = true;
}

bool DeviceGrabber::waitRetry() {
  std::unique_lock<std::mutex> lock(mutex_);
  return !wake_.wait_for(lock, std::chrono::duration<double>(config_.retry_s),
                         [this] { return stop_; });
}

void DeviceGrabber::report(const std::string& problem) {
  const bool changed = problem != problem_;
  problem_ = problem;
  if (problem.empty()) {
    if (changed && log_) log_->info("camera '" + camera_id_ + "': " + device_ + " delivers frames");
  } else if (log_) {
    // The first time as a warning, the retries only at debug level.
    log_->write(changed ? LogLevel::kWarn : LogLevel::kDebug, problem);
  }
  if (changed) on_problem_(problem);
}

void DeviceGrabber::grabUntilStopped() {
  const std::string who = "camera '" + camera_id_ + "': " + device_;
  char retry_text[64];
  std::snprintf(retry_text, sizeof(retry_text), "; retrying every %g s", config_.retry_s);
  const std::string retry = retry_text;
  const std::size_t frame_bytes = static_cast<std::size_t>(width_) * height_ * 2;
  while (true) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stop_) return;
    }
    ++attempts_;
    if (!std::filesystem::exists(device_)) {
      report(who + " does not exist" + retry);
      if (!waitRetry()) return;
      continue;
    }
    cv::VideoCapture capture;
    // Raw YUYV as the NAO's cameras deliver it: the pipeline reads YUYV itself, so a
    // conversion in the driver would cost time and chroma for nothing.
    const bool opened = capture.open(
        device_, cv::CAP_V4L2,
        {cv::CAP_PROP_FRAME_WIDTH, width_, cv::CAP_PROP_FRAME_HEIGHT, height_, cv::CAP_PROP_FOURCC,
         cv::VideoWriter::fourcc('Y', 'U', 'Y', 'V'), cv::CAP_PROP_CONVERT_RGB, 0});
    if (!opened) {
      report(who + " cannot be opened as a V4L2 camera" + retry);
      if (!waitRetry()) return;
      continue;
    }
    cv::Mat raw;
    while (true) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stop_) return;
      }
      if (!capture.grab()) {
        report(who + " stopped delivering frames" + retry);
        break;
      }
      const std::int64_t utime = monotonicMicros();  // at capture, the node's clock
      if (!capture.retrieve(raw) || raw.total() * raw.elemSize() != frame_bytes ||
          !raw.isContinuous()) {
        report(who + " does not deliver " + std::to_string(width_) + "x" + std::to_string(height_) +
               " YUYV frames (camera.yaml's size)" + retry);
        break;
      }
      report("");
      image_t msg;
      msg.utime = utime;
      msg.camera_id = camera_id_;
      msg.width = width_;
      msg.height = height_;
      msg.pixel_format = image_t::PIXEL_FORMAT_YUYV;
      msg.row_stride = width_ * 2;
      msg.size = static_cast<std::int32_t>(frame_bytes);
      msg.data.assign(raw.data, raw.data + frame_bytes);
      on_image_(std::move(msg));
    }
    capture.release();
    if (!waitRetry()) return;
  }
}

}  // namespace houghloc
