// houghloc-play publishes a rendered folder into an LCM file:// log (no network); the log holds
// every frame's odometry, camera pose and YUYV image (bytes of bgrToYuyv of the recorded image),
// every ground-truth row, re-stamped with the recorded offsets.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "houghloc/camera_pose_t.hpp"
#include "houghloc/image_t.hpp"
#include "houghloc/odometry_t.hpp"
#include "houghloc/pose_hypotheses_t.hpp"
#include "tools/lcm/message_conversion.h"
#include "tools/recording/recording.h"
#include "vision/image_conversion.h"

namespace houghloc {
namespace {

// The log to check: HOUGHLOC_PLAY_LOG (an lcm-logger log of houghloc-play over udpm://) or one
// this test writes through LCM's file:// provider.
std::string logPath() {
  if (const char* log = std::getenv("HOUGHLOC_PLAY_LOG")) return log;
  return std::string(HOUGHLOC_PLAY_WORK) + "/play.log";
}

TEST(PlayLog, PublishesEveryMessageRestamped) {
  const std::string folder = HOUGHLOC_PLAY_FIXTURE;
  const Recording rec = readRecording(folder);
  std::filesystem::create_directories(HOUGHLOC_PLAY_WORK);
  const std::string log = logPath();
  if (!std::getenv("HOUGHLOC_PLAY_LOG")) {  // else play_udpm_test.sh recorded it over udpm://
    std::filesystem::remove(log);
    const std::string cmd = std::string(HOUGHLOC_PLAY_EXE) + " " + folder +
                            " --speed 10 --channel-prefix T_ --lcm-url 'file://" + log +
                            "?mode=w' 2>/dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  }

  lcm::LogFile file(log, "r");
  ASSERT_TRUE(file.good());
  std::map<std::string, int> counts;
  std::int64_t base = -1;
  int image_index = 0, odo_index = 0, truth_index = 0;
  const std::int64_t t0 = rec.frames.front().t_us;
  while (const lcm::LogEvent* event = file.readNextEvent()) {
    ++counts[event->channel];
    if (event->channel == "T_ODOMETRY") {
      odometry_t msg;
      ASSERT_GT(msg.decode(event->data, 0, event->datalen), 0);
      if (base < 0) base = msg.utime - t0;
      const FrameRecord& f = rec.frames[odo_index++];
      ASSERT_TRUE(f.odometry.has_value());
      EXPECT_EQ(msg.utime, base + f.t_us);
      EXPECT_DOUBLE_EQ(msg.x, f.odometry->x);
      EXPECT_DOUBLE_EQ(msg.theta, f.odometry->theta);
    } else if (event->channel == "T_IMAGE") {
      image_t msg;
      ASSERT_GT(msg.decode(event->data, 0, event->datalen), 0);
      const FrameRecord& f = rec.frames[image_index++];
      EXPECT_EQ(msg.utime, base + f.t_us);
      EXPECT_EQ(msg.camera_id, f.camera_id);
      EXPECT_EQ(int{msg.pixel_format}, int{image_t::PIXEL_FORMAT_YUYV});
      if (image_index % 10 == 1) {  // a few full comparisons keep the test fast
        const cv::Mat bgr = cv::imread(folder + "/" + f.image, cv::IMREAD_COLOR);
        EXPECT_EQ(cv::norm(imageFromMessage(msg), bgrToYuyv(bgr), cv::NORM_INF), 0.0);
      }
    } else if (event->channel == "T_GROUND_TRUTH") {
      pose_hypotheses_t msg;
      ASSERT_GT(msg.decode(event->data, 0, event->datalen), 0);
      const GroundTruthRecord& g = rec.ground_truth[truth_index++];
      EXPECT_EQ(msg.utime, base + g.t_us);
      ASSERT_EQ(msg.num_hypotheses, 1);
      EXPECT_DOUBLE_EQ(msg.hypotheses[0].x, g.field_T_robot.x);
    } else if (event->channel == "T_CAMERA_POSE") {
      camera_pose_t msg;
      ASSERT_GT(msg.decode(event->data, 0, event->datalen), 0);
      EXPECT_TRUE(cameraPoseFromMessage(msg).has_value());
    }
  }
  const int frames = static_cast<int>(rec.frames.size());
  EXPECT_EQ(counts["T_IMAGE"], frames);
  EXPECT_EQ(counts["T_ODOMETRY"], frames);
  EXPECT_EQ(counts["T_CAMERA_POSE"], frames);
  EXPECT_EQ(counts["T_GROUND_TRUTH"], static_cast<int>(rec.ground_truth.size()));
  EXPECT_EQ(counts["T_HINT"], static_cast<int>(rec.hints.size()));
  EXPECT_GT(rec.ground_truth.size(), 0u);
}

// Runs after PublishesEveryMessageRestamped (same binary, declaration order) on its log.
TEST(PlayLog, JavaDecodesPoseHypothesesFromTheLog) {
#ifndef HOUGHLOC_JAVAC
  GTEST_SKIP() << "no JDK or lcm.jar at configure time (tools/setup.sh installs them)";
#else
  const Recording rec = readRecording(HOUGHLOC_PLAY_FIXTURE);
  const std::string work = HOUGHLOC_PLAY_WORK;
  const std::string compile = std::string(HOUGHLOC_JAVAC) + " -cp " + HOUGHLOC_JAVA_CP + " -d " +
                              work + " " + HOUGHLOC_JAVA_SRC;
  ASSERT_EQ(std::system(compile.c_str()), 0) << compile;
  const std::string run = std::string(HOUGHLOC_JAVA) + " -cp " + HOUGHLOC_JAVA_CP + ":" + work +
                          " DecodeHypotheses " + logPath() + " T_GROUND_TRUTH";
  FILE* pipe = popen(run.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  long long count = 0, utime = 0;
  double x = 0.0;
  ASSERT_EQ(std::fscanf(pipe, "%lld %lld %lf", &count, &utime, &x), 3) << run;
  ASSERT_EQ(pclose(pipe), 0);
  EXPECT_EQ(count, static_cast<long long>(rec.ground_truth.size()));
  EXPECT_GT(utime, 0);
  EXPECT_NEAR(x, rec.ground_truth.front().field_T_robot.x, 1e-12);
#endif
}

}  // namespace
}  // namespace houghloc
