// houghloc-play publishes a rendered folder into an LCM file:// log (no network); the log holds
// every frame's odometry, camera pose and YUYV image (bytes of bgrToYuyv of the recorded image),
// every ground-truth row, re-stamped with the recorded offsets.
#include <gtest/gtest.h>

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

TEST(PlayLog, PublishesEveryMessageRestamped) {
  const std::string folder = HOUGHLOC_PLAY_FIXTURE;
  const Recording rec = readRecording(folder);
  std::filesystem::create_directories(HOUGHLOC_PLAY_WORK);
  const std::string log = std::string(HOUGHLOC_PLAY_WORK) + "/play.log";
  std::filesystem::remove(log);
  const std::string cmd = std::string(HOUGHLOC_PLAY_EXE) + " " + folder +
                          " --speed 10 --channel-prefix T_ --lcm-url 'file://" + log +
                          "?mode=w' 2>/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;

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
      EXPECT_EQ(msg.utime, base + f.t_us);
      EXPECT_DOUBLE_EQ(msg.x, f.odometry.x);
      EXPECT_DOUBLE_EQ(msg.theta, f.odometry.theta);
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

}  // namespace
}  // namespace houghloc
