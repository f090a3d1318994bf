#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "houghloc/image_t.hpp"
#include "tools/node/node_log.h"

namespace houghloc {

/// houghloc-node --device ID=/dev/videoN.
struct DeviceGrabberConfig {
  double retry_s = 2.0;  ///< a device that is missing, cannot be opened or stops: retry after, s
};

/// Grabs one camera with cv::VideoCapture (V4L2) on its own thread: raw YUYV at the
/// camera.yaml's size, no RGB conversion in the driver (CAP_PROP_CONVERT_RGB = 0), each frame
/// stamped with CLOCK_MONOTONIC when grab() returns (the node's clock, tools/lcm/clock.h), and
/// handed over as a YUYV image_t. Never gives up: a device that is missing or fails is reported
/// (log and `on_problem`, which gets "" once frames flow again) and retried every retry_s.
class DeviceGrabber {
 public:
  DeviceGrabber(std::string camera_id, std::string device, int width, int height,
                std::function<void(image_t)> on_image,
                std::function<void(const std::string&)> on_problem, NodeLog* log,
                const DeviceGrabberConfig& config = {});
  ~DeviceGrabber() { stop(); }
  DeviceGrabber(const DeviceGrabber&) = delete;
  DeviceGrabber& operator=(const DeviceGrabber&) = delete;

  void start();
  /// Asks the thread to end (after the grab under way, at once while waiting to retry).
  void requestStop();
  /// The thread has ended. A grab blocked in the driver (V4L2 waits up to 10 s for a frame of
  /// a stalled camera) keeps this false for that long.
  bool finished() const { return finished_; }
  /// requestStop(), then waits for the thread.
  void stop();
  int attempts() const { return attempts_; }  ///< tries to open the device so far

 private:
  void loop();
  void grabUntilStopped();
  void report(const std::string& problem);
  bool waitRetry();  ///< false when stopped while waiting

  std::string camera_id_, device_;
  int width_, height_;
  std::function<void(image_t)> on_image_;
  std::function<void(const std::string&)> on_problem_;
  NodeLog* log_;
  DeviceGrabberConfig config_;
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::atomic<int> attempts_{0};
  std::atomic<bool> finished_{false};
  std::string problem_;  ///< the last one reported ("" while frames flow)
};

}  // namespace houghloc
