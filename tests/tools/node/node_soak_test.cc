// Soak of houghloc-node: NodeRunner (its LCM thread and processing thread, as in the process)
// over memq:// with 36 000 images of two 640x480 YUYV cameras, the rendered two-camera walk of
// the latency test looped (a jump to the start pose at every loop's end), each image published
// with its odometry and camera pose as soon as the previous image's HYPOTHESES arrived (fed as
// fast as it processes). Asserted: every image answered and none dropped, resident memory grows
// by less than 5 MB after the first 1 000 images, the hypotheses stay within the tracker's
// bound and finite, and the process CPU time of the last 1 000 images is within 1.25x of the
// first 1 000 (each the median of its 100-image blocks x 10, so that other tests running beside
// it under ctest -j2 do not decide it). Release only (label slow).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <lcm/lcm-cpp.hpp>
#include <mutex>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/tools/node/memq_node.h"
#include "tests/tools/pipeline/soak_support.h"
#include "tools/lcm/message_conversion.h"

namespace houghloc {
namespace {

constexpr int kImages = 36000;
constexpr int kWindow = 1000;
constexpr int kBlock = 100;  // images per CPU block (windowCpuSeconds)

/// A NodeRunner on its own thread and a subscriber on the same memq:// LCM that keeps only what
/// the soak asserts (so that the test itself does not grow).
class SoakedNode {
 public:
  explicit SoakedNode(NodeCore& core) : node_(core) {
    node_.lcm().subscribe("HYPOTHESES", &SoakedNode::onHypotheses, this);
    node_.start();
  }

  template <typename T>
  void publish(const std::string& channel, const T& msg) {
    node_.publish(channel, msg);
  }
  /// Waits up to 10 s for the HYPOTHESES of the image stamped `utime`.
  bool waitAnswer(std::int64_t utime) {
    std::unique_lock<std::mutex> lock(mutex_);
    return wake_.wait_for(lock, std::chrono::seconds(10), [&] { return last_utime_ == utime; });
  }
  int mostHypotheses() {
    std::lock_guard<std::mutex> lock(mutex_);
    return most_hypotheses_;
  }
  int nonFinite() {
    std::lock_guard<std::mutex> lock(mutex_);
    return non_finite_;
  }

 private:
  void onHypotheses(const lcm::ReceiveBuffer*, const std::string&, const pose_hypotheses_t* m) {
    std::lock_guard<std::mutex> lock(mutex_);
    last_utime_ = m->utime;
    most_hypotheses_ = std::max(most_hypotheses_, static_cast<int>(m->num_hypotheses));
    for (const pose_hypothesis_t& h : m->hypotheses) {
      const bool finite = std::isfinite(h.x) && std::isfinite(h.y) && std::isfinite(h.theta) &&
                          std::isfinite(h.weight);
      non_finite_ += finite ? 0 : 1;
    }
    wake_.notify_all();
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::int64_t last_utime_ = -1;
  int most_hypotheses_ = 0;
  int non_finite_ = 0;
  MemqNode node_;  ///< last: stopped before the members its handler touches go
};

TEST(NodeSoak, ThirtySixThousandImagesOfTwoCamerasKeepMemoryHypothesesAndTimeBounded) {
  cv::setNumThreads(0);  // as houghloc-node runs (tools/node/main.cc): no OpenCV worker pool
  const Recording rec = readRecording(HOUGHLOC_NODE_SOAK_FIXTURE);
  ASSERT_TRUE(rec.field);
  std::map<std::string, CameraIntrinsics> cameras;
  std::vector<image_t> images;  // the robot's YUYV messages, re-stamped before publishing
  for (const FrameRecord& f : rec.frames) {
    cameras[f.camera_id] = rec.intrinsicsFor(f);
    const cv::Mat bgr = cv::imread(rec.folder + "/" + f.image, cv::IMREAD_COLOR);
    ASSERT_FALSE(bgr.empty()) << f.image;
    images.push_back(imageToMessage(bgr, image_t::PIXEL_FORMAT_YUYV, 0, f.camera_id));
  }
  ASSERT_EQ(cameras.size(), 2u) << "the soak fixture has a top and a bottom camera";

  PipelineConfig config;
  NodeCore core(std::make_shared<const FieldModel>(*rec.field), config, cameras);
  const int max_hypotheses = config.localizer.tracker.set.max_hypotheses;
  LoopedRun run({rec.frames});
  std::vector<double> cpu_first{processCpuSeconds()}, cpu_last;  // readings, see windowCpuSeconds
  double rss_after_first = 0.0;
  {
    SoakedNode node(core);
    for (int n = 0; n < kImages; ++n) {
      if (n == kImages - kWindow) cpu_last.push_back(processCpuSeconds());
      const LoopedStep step = run.step();
      const PipelineFrame& f = step.frame;
      node.publish("ODOMETRY", odometryToMessage(f.t_us, *f.odometry));
      node.publish("CAMERA_POSE", cameraPoseToMessage(f.t_us, f.camera_id, f.robot_T_camera));
      image_t& image = images[step.index];
      image.utime = f.t_us;
      node.publish("IMAGE", image);
      ASSERT_TRUE(node.waitAnswer(f.t_us)) << "no HYPOTHESES for image " << n;
      if (n < kWindow) cpu_first.push_back(processCpuSeconds());
      if (n >= kImages - kWindow) cpu_last.push_back(processCpuSeconds());
      if (n == kWindow - 1) rss_after_first = residentMegabytes();
      if ((n + 1) % 6000 == 0) {
        std::printf("node soak: %d images, resident %.1f MB, most hypotheses %d\n", n + 1,
                    residentMegabytes(), node.mostHypotheses());
        std::fflush(stdout);
      }
    }
    const double first = windowCpuSeconds(cpu_first, kBlock);
    const double last = windowCpuSeconds(cpu_last, kBlock);
    const double rss_growth = residentMegabytes() - rss_after_first;
    std::printf(
        "node soak: resident growth after image %d: %.2f MB; process CPU first %d images "
        "%.2f s, last %.2f s (ratio %.3f; medians of %d-image blocks, totals %.2f / %.2f s); "
        "most hypotheses %d of %d; images dropped %lld\n",
        kWindow, rss_growth, kWindow, first, last, last / first, kBlock,
        cpu_first.back() - cpu_first.front(), cpu_last.back() - cpu_last.front(),
        node.mostHypotheses(), max_hypotheses, static_cast<long long>(core.drops().total()));
    EXPECT_LT(rss_growth, 5.0);
    EXPECT_LE(node.mostHypotheses(), max_hypotheses);
    EXPECT_EQ(node.nonFinite(), 0);
    EXPECT_LE(last, 1.25 * first);
  }
  EXPECT_EQ(core.drops().total(), 0);
  EXPECT_EQ(core.status().frames_processed, kImages);
}

}  // namespace
}  // namespace houghloc
