// Runs the C++ and Java publisher examples of docs/lcm.md into LCM file:// logs and decodes what
// they published.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <string>
#include <vector>

#include "houghloc/camera_pose_t.hpp"
#include "houghloc/image_t.hpp"
#include "houghloc/localization_hint_t.hpp"
#include "houghloc/odometry_t.hpp"

namespace houghloc {
namespace {

// The last message of each channel (LogFile reuses an event's buffer, so the bytes are copied).
std::map<std::string, std::vector<std::uint8_t>> readLog(const std::string& path) {
  std::map<std::string, std::vector<std::uint8_t>> events;
  lcm::LogFile file(path, "r");
  EXPECT_TRUE(file.good()) << path;
  while (const lcm::LogEvent* e = file.readNextEvent()) {
    const auto* bytes = static_cast<const std::uint8_t*>(e->data);
    events[e->channel].assign(bytes, bytes + e->datalen);
  }
  return events;
}

template <typename T>
T decodeEvent(const std::vector<std::uint8_t>& bytes) {
  T msg;
  EXPECT_EQ(msg.decode(bytes.data(), 0, static_cast<int>(bytes.size())),
            static_cast<int>(bytes.size()));
  return msg;
}

std::string freshLog(const std::string& name) {
  std::filesystem::create_directories(HOUGHLOC_EXAMPLE_WORK);
  const std::string log = std::string(HOUGHLOC_EXAMPLE_WORK) + "/" + name;
  std::filesystem::remove(log);
  return log;
}

TEST(PublisherExamples, CppPublishesTheRobotInputs) {
  const std::string log = freshLog("cpp.log");
  const std::string cmd = std::string(HOUGHLOC_CPP_PUBLISHER) + " 'file://" + log + "?mode=w'";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  auto events = readLog(log);
  ASSERT_EQ(events.size(), 4u);
  const auto odo = decodeEvent<odometry_t>(events["ODOMETRY"]);
  const auto cam = decodeEvent<camera_pose_t>(events["CAMERA_POSE"]);
  const auto img = decodeEvent<image_t>(events["IMAGE"]);
  const auto hint = decodeEvent<localization_hint_t>(events["HINT"]);
  EXPECT_EQ(odo.x, 1.25);
  EXPECT_EQ(cam.camera_id, "top");
  EXPECT_EQ(img.size, 640 * 480 * 2);
  EXPECT_EQ(img.utime, cam.utime);  // one clock, the image's time
  EXPECT_EQ(int{hint.kind}, int{localization_hint_t::ADD});
  ASSERT_EQ(hint.num_poses, 2);
  EXPECT_EQ(hint.poses[1].y, 3.0);
}

TEST(PublisherExamples, JavaPublishesTheRobotInputs) {
#ifndef HOUGHLOC_JAVAC
  GTEST_SKIP() << "no JDK or lcm.jar at configure time (tools/setup.sh installs them)";
#else
  const std::string log = freshLog("java.log");
  const std::string classes = std::string(HOUGHLOC_EXAMPLE_WORK) + "/classes";
  const std::string compile = std::string(HOUGHLOC_JAVAC) + " -cp " + HOUGHLOC_JAVA_CP + " -d " +
                              classes + " " + HOUGHLOC_JAVA_PUBLISHER;
  ASSERT_EQ(std::system(compile.c_str()), 0) << compile;
  const std::string run = std::string(HOUGHLOC_JAVA) + " -cp " + HOUGHLOC_JAVA_CP + ":" + classes +
                          " RobotPublisher 'file://" + log + "?mode=w'";
  ASSERT_EQ(std::system(run.c_str()), 0) << run;
  auto events = readLog(log);
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(decodeEvent<odometry_t>(events["ODOMETRY"]).theta, 0.05);
  EXPECT_EQ(decodeEvent<camera_pose_t>(events["CAMERA_POSE"]).pitch, 0.37);
  EXPECT_EQ(int{decodeEvent<localization_hint_t>(events["HINT"]).kind},
            int{localization_hint_t::OWN_HALF});
#endif
}

}  // namespace
}  // namespace houghloc
