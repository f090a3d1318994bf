// Soak of houghloc-node: NodeRunner (its LCM thread and processing thread, as in the process)
// over memq:// with 36 000 images of two 640x480 YUYV cameras, the rendered two-camera walk of
// the latency test looped (a jump to the start pose at every loop's end), each image published
// with its odometry and camera pose as soon as the previous image's HYPOTHESES arrived (fed as
// fast as it processes). Asserted: every image answered and none dropped, resident memory grows
// by less than 5 MB after the first 1 000 images, the hypotheses stay within the tracker's
// bound and finite, and the process CPU time of a pass through the loop at the end is within
// 1.25x of one at the start: the median over the last 5 passes against the median over passes
// 2-6 (the first starts without a track). Whole passes, because a pass's CPU depends on where it
// is cut (the jump back at its end costs global runs: 1 000-image windows varied by 40 % with no
// growth), and medians, so that other tests running beside it under ctest -j2 do not decide it.
// Release only (label slow).
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
constexpr int kWindow = 1000;  // images before the memory baseline
constexpr int kPasses = 5;     // passes through the loop in each CPU window

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
  std::vector<double> pass_start_cpu;  // process CPU at the start of each pass through the loop
  pass_start_cpu.reserve(kImages / rec.frames.size() + 2);
  double rss_after_first = 0.0;
  {
    SoakedNode node(core);
    for (int n = 0; n < kImages; ++n) {
      const LoopedStep step = run.step();
      if (step.index == 0) pass_start_cpu.push_back(processCpuSeconds());
      const PipelineFrame& f = step.frame;
      node.publish("ODOMETRY", odometryToMessage(f.t_us, *f.odometry));
      node.publish("CAMERA_POSE", cameraPoseToMessage(f.t_us, f.camera_id, f.robot_T_camera));
      image_t& image = images[step.index];
      image.utime = f.t_us;
      node.publish("IMAGE", image);
      ASSERT_TRUE(node.waitAnswer(f.t_us)) << "no HYPOTHESES for image " << n;
      if (n == kWindow - 1) rss_after_first = residentMegabytes();
      if ((n + 1) % 6000 == 0) {
        std::printf("node soak: %d images, resident %.1f MB, most hypotheses %d\n", n + 1,
                    residentMegabytes(), node.mostHypotheses());
        std::fflush(stdout);
      }
    }
    if (run.step().index == 0) pass_start_cpu.push_back(processCpuSeconds());  // a last end
    std::vector<double> pass_cpu;  // complete passes only
    for (std::size_t k = 0; k + 1 < pass_start_cpu.size(); ++k)
      pass_cpu.push_back(pass_start_cpu[k + 1] - pass_start_cpu[k]);
    ASSERT_GE(pass_cpu.size(), 2u * kPasses + 1);
    const double first = medianOf({pass_cpu.begin() + 1, pass_cpu.begin() + 1 + kPasses});
    const double last = medianOf({pass_cpu.end() - kPasses, pass_cpu.end()});
    const double rss_growth = residentMegabytes() - rss_after_first;
    std::printf(
        "node soak: resident growth after image %d: %.2f MB; process CPU per pass of %zu images "
        "(median of %d passes) %.3f s at the start, %.3f s at the end (ratio %.3f), the first "
        "pass %.3f s, fastest and slowest pass %.3f / %.3f s; most hypotheses %d of %d; images "
        "dropped %lld\n",
        kWindow, rss_growth, rec.frames.size(), kPasses, first, last, last / first, pass_cpu[0],
        *std::min_element(pass_cpu.begin(), pass_cpu.end()),
        *std::max_element(pass_cpu.begin(), pass_cpu.end()), node.mostHypotheses(), max_hypotheses,
        static_cast<long long>(core.drops().total()));
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
