// Soak of houghloc-node: NodeRunner (its LCM thread and processing thread, as in the process)
// over memq:// with 36 000 images of two 640x480 YUYV cameras, the rendered two-camera walk of
// the latency test looped (a jump to the start pose at every loop's end), each image published
// with its odometry and camera pose as soon as the previous image's HYPOTHESES arrived (fed as
// fast as it processes). Asserted: every image answered and none dropped, resident memory grows
// by less than 5 MB after the first 1 000 images, the hypotheses stay within the tracker's
// bound and finite, and the process CPU time of the last 1 000 images is within 1.25x of the
// first 1 000. Release only (label slow).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <lcm/lcm-cpp.hpp>
#include <mutex>
#include <opencv2/imgcodecs.hpp>
#include <thread>

#include "tests/tools/pipeline/soak_support.h"
#include "tools/lcm/message_conversion.h"
#include "tools/node/node_runner.h"

namespace houghloc {
namespace {

constexpr int kImages = 36000;
constexpr int kWindow = 1000;

/// A NodeRunner on its own thread and a subscriber on the same memq:// LCM that keeps only what
/// the soak asserts (so that the test itself does not grow).
class SoakedNode {
 public:
  explicit SoakedNode(NodeCore& core) : lcm_("memq://"), runner_(lcm_, core, "", true) {
    lcm_.subscribe("HYPOTHESES", &SoakedNode::onHypotheses, this);
    thread_ = std::thread([this] { runner_.run(stop_); });
  }
  ~SoakedNode() {
    stop_ = true;
    thread_.join();
  }

  template <typename T>
  void publish(const std::string& channel, const T& msg) {
    lcm_.publish(channel, &msg);
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

  lcm::LCM lcm_;
  NodeRunner runner_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::int64_t last_utime_ = -1;
  int most_hypotheses_ = 0;
  int non_finite_ = 0;
};

TEST(NodeSoak, ThirtySixThousandImagesOfTwoCamerasKeepMemoryHypothesesAndTimeBounded) {
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
  double cpu_first = 0.0, cpu_last_start = 0.0, rss_after_first = 0.0;
  {
    SoakedNode node(core);
    const double cpu_start = processCpuSeconds();
    for (int n = 0; n < kImages; ++n) {
      if (n == kImages - kWindow) cpu_last_start = processCpuSeconds();
      const LoopedStep step = run.step();
      const PipelineFrame& f = step.frame;
      node.publish("ODOMETRY", odometryToMessage(f.t_us, *f.odometry));
      node.publish("CAMERA_POSE", cameraPoseToMessage(f.t_us, f.camera_id, f.robot_T_camera));
      image_t& image = images[step.index];
      image.utime = f.t_us;
      node.publish("IMAGE", image);
      ASSERT_TRUE(node.waitAnswer(f.t_us)) << "no HYPOTHESES for image " << n;
      if (n == kWindow - 1) {
        cpu_first = processCpuSeconds() - cpu_start;
        rss_after_first = residentMegabytes();
      }
      if ((n + 1) % 6000 == 0) {
        std::printf("node soak: %d images, resident %.1f MB, most hypotheses %d\n", n + 1,
                    residentMegabytes(), node.mostHypotheses());
        std::fflush(stdout);
      }
    }
    const double cpu_last = processCpuSeconds() - cpu_last_start;
    const double rss_growth = residentMegabytes() - rss_after_first;
    std::printf(
        "node soak: resident growth after image %d: %.2f MB; process CPU first %d images "
        "%.2f s, last %.2f s (ratio %.3f); most hypotheses %d of %d; images dropped %lld\n",
        kWindow, rss_growth, kWindow, cpu_first, cpu_last, cpu_last / cpu_first,
        node.mostHypotheses(), max_hypotheses, static_cast<long long>(core.drops().total()));
    EXPECT_LT(rss_growth, 5.0);
    EXPECT_LE(node.mostHypotheses(), max_hypotheses);
    EXPECT_EQ(node.nonFinite(), 0);
    EXPECT_LE(cpu_last, 1.25 * cpu_first);
  }
  EXPECT_EQ(core.drops().total(), 0);
  EXPECT_EQ(core.status().frames_processed, kImages);
}

}  // namespace
}  // namespace houghloc
