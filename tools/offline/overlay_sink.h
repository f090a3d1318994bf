#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "tools/offline/offline_context.h"

namespace cv {
class VideoWriter;
}

namespace houghloc {

/// Where overlays go: OUT/overlay/<image stem>.png with --overlay, and the --video file.
/// The video has the first camera's image size (other sizes are resized) and the recording's
/// frame rate (median frame interval; 30 fps when unknown); .avi uses MJPG, anything else mp4v.
class OverlaySink {
 public:
  /// Opens the video before any frame runs; throws std::runtime_error naming the file when the
  /// codec is unavailable in this OpenCV build or the file cannot be created.
  explicit OverlaySink(const OfflineContext& context);
  ~OverlaySink();

  /// True when overlays are wanted at all (--overlay or --video).
  bool active() const { return png_ || video_ != nullptr; }
  void write(const FrameRecord& frame, const cv::Mat& overlay);
  /// Finishes the video; throws when a PNG could not be written earlier.
  void close();

 private:
  std::string dir_;
  bool png_ = false;
  std::unique_ptr<cv::VideoWriter> video_;
  cv::Size video_size_;
  std::string failed_png_;
};

}  // namespace houghloc
