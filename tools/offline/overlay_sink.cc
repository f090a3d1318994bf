#include "tools/offline/overlay_sink.h"

#include <algorithm>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <stdexcept>
#include <vector>

namespace houghloc {
namespace {

namespace fs = std::filesystem;

double recordingFps(const OfflineContext& context) {
  std::vector<std::int64_t> dt;
  const auto& frames = context.recording.frames;
  for (int i = context.first_frame + 1; i < context.end_frame; ++i) {
    const std::int64_t d = frames[i].t_us - frames[i - 1].t_us;
    if (d > 0) dt.push_back(d);
  }
  if (dt.empty()) return 30.0;
  std::nth_element(dt.begin(), dt.begin() + dt.size() / 2, dt.end());
  return std::clamp(1e6 / static_cast<double>(dt[dt.size() / 2]), 1.0, 240.0);
}

}  // namespace

OverlaySink::OverlaySink(const OfflineContext& context)
    : dir_((fs::path(context.out_dir) / "overlay").string()), png_(context.options.overlay) {
  if (png_) {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec) throw std::runtime_error(dir_ + ": cannot create overlay folder: " + ec.message());
  }
  const std::string& path = context.options.video_file;
  if (path.empty() || context.first_frame >= context.end_frame) return;
  const CameraIntrinsics& camera =
      context.recording.intrinsicsFor(context.recording.frames[context.first_frame]);
  video_size_ = {camera.image_width, camera.image_height};
  const bool avi = fs::path(path).extension() == ".avi";
  const int fourcc = avi ? cv::VideoWriter::fourcc('M', 'J', 'P', 'G')
                         : cv::VideoWriter::fourcc('m', 'p', '4', 'v');
  video_ = std::make_unique<cv::VideoWriter>();
  bool opened = false;
  try {
    opened = video_->open(path, fourcc, recordingFps(context), video_size_, true);
  } catch (const cv::Exception& e) {
    opened = false;
  }
  if (!opened) {
    video_.reset();
    throw std::runtime_error(path + ": cannot write a video with the " +
                             std::string(avi ? "MJPG" : "mp4v") +
                             " codec (not available in this OpenCV build, or the folder is not "
                             "writable); try a .avi file (MJPG)");
  }
}

OverlaySink::~OverlaySink() = default;

void OverlaySink::write(const FrameRecord& frame, const cv::Mat& overlay) {
  if (png_) {
    const std::string path =
        (fs::path(dir_) / (fs::path(frame.image).stem().string() + ".png")).string();
    if (!cv::imwrite(path, overlay) && failed_png_.empty()) failed_png_ = path;
  }
  if (video_) {
    if (overlay.size() == video_size_) {
      video_->write(overlay);
    } else {
      cv::Mat resized;
      cv::resize(overlay, resized, video_size_);
      video_->write(resized);
    }
  }
}

void OverlaySink::close() {
  if (video_) video_->release();
  video_.reset();
  if (!failed_png_.empty()) throw std::runtime_error(failed_png_ + ": cannot write overlay");
}

}  // namespace houghloc
