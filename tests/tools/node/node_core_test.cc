// NodeCore fed a rendered recording's messages in houghloc-play's order gives houghloc-offline's
// poses on that folder; bad inputs are counted per reason and never stop it.
#include "tools/node/node_core.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "tools/lcm/message_conversion.h"
#include "tools/recording/recording.h"

namespace houghloc {
namespace {

struct PoseRow {
  std::int64_t t_us;
  double x, y, theta;
  std::string status;
};

std::vector<PoseRow> readPoses(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  std::vector<PoseRow> rows;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string cell;
    std::vector<std::string> cells;
    while (std::getline(s, cell, ',')) cells.push_back(cell);
    rows.push_back({std::stoll(cells[0]), std::stod(cells[1]), std::stod(cells[2]),
                    std::stod(cells[3]), cells[9]});
  }
  return rows;
}

const char* statusName(std::int8_t status) {
  static const char* names[] = {"INITIALIZING", "TRACKING", "AMBIGUOUS", "LOST"};
  return names[status];
}

class NodeCoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    rec_ = readRecording(HOUGHLOC_NODE_FIXTURE);
    ASSERT_TRUE(rec_.field.has_value());
    for (const FrameRecord& f : rec_.frames) cameras_[f.camera_id] = rec_.intrinsicsFor(f);
  }
  std::unique_ptr<NodeCore> makeCore() {
    return std::make_unique<NodeCore>(std::make_shared<const FieldModel>(*rec_.field),
                                      PipelineConfig{}, cameras_);
  }
  image_t imageMessage(const FrameRecord& f, std::int8_t format) const {
    const cv::Mat bgr = cv::imread(rec_.folder + "/" + f.image, cv::IMREAD_COLOR);
    return imageToMessage(bgr, format, f.t_us, f.camera_id);
  }
  Recording rec_;
  std::map<std::string, CameraIntrinsics> cameras_;
};

TEST_F(NodeCoreTest, GivesTheOfflinePoses) {
  const std::string out = std::string(HOUGHLOC_NODE_WORK) + "/offline";
  std::filesystem::remove_all(out);
  const std::string cmd = std::string(HOUGHLOC_OFFLINE_EXE) + " " + rec_.folder + " -o " + out +
                          " --quiet > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const std::vector<PoseRow> offline = readPoses(out + "/poses.csv");
  ASSERT_EQ(offline.size(), rec_.frames.size());

  auto core = makeCore();
  ASSERT_TRUE(rec_.hints.empty());  // hints go through queueHint as in houghloc-offline
  std::size_t with_pose = 0;
  for (std::size_t i = 0; i < rec_.frames.size(); ++i) {
    const FrameRecord& f = rec_.frames[i];
    core->onOdometry(odometryToMessage(f.t_us, f.odometry.value()));
    core->onCameraPose(cameraPoseToMessage(f.t_us, f.camera_id, f.robot_T_camera));
    // BGR8: the pixels houghloc-offline reads (YUYV would subsample the chroma).
    const std::optional<NodeOutput> result = core->onImage(imageMessage(f, 0));
    ASSERT_TRUE(result.has_value()) << "frame " << i << ": " << core->status().message;
    const pose_hypotheses_t& h = result->hypotheses;
    EXPECT_EQ(h.utime, f.t_us);
    EXPECT_EQ(statusName(h.status), offline[i].status) << "frame " << i;
    if (h.num_hypotheses == 0) continue;
    ++with_pose;
    EXPECT_NEAR(h.hypotheses[0].x, offline[i].x, 1e-6) << "frame " << i;  // poses.csv's digits
    EXPECT_NEAR(h.hypotheses[0].y, offline[i].y, 1e-6) << "frame " << i;
    EXPECT_NEAR(h.hypotheses[0].theta, offline[i].theta, 1e-6) << "frame " << i;
  }
  EXPECT_GT(with_pose, rec_.frames.size() / 2);
  const localizer_status_t status = core->status();
  EXPECT_EQ(status.frames_processed, static_cast<std::int64_t>(rec_.frames.size()));
  EXPECT_EQ(core->drops().total(), 0);
}

TEST_F(NodeCoreTest, CountsEveryRefusalAndKeepsGoing) {
  auto core = makeCore();
  const FrameRecord& f = rec_.frames[0];
  const double nan = std::numeric_limits<double>::quiet_NaN();
  image_t image = imageMessage(f, 1);
  EXPECT_FALSE(core->onImage(image).has_value());  // no camera pose yet
  EXPECT_EQ(core->drops().no_camera_pose, 1);

  Pose3 bad = f.robot_T_camera;
  bad.pitch = nan;
  core->onCameraPose(cameraPoseToMessage(f.t_us, f.camera_id, bad));
  core->onOdometry(odometryToMessage(f.t_us, Pose2(nan, 0.0, 0.0)));
  EXPECT_EQ(core->drops().malformed, 2);
  EXPECT_FALSE(core->onImage(image).has_value());  // the NaN pose never arrived
  EXPECT_EQ(core->drops().no_camera_pose, 2);

  core->onCameraPose(cameraPoseToMessage(f.t_us, f.camera_id, f.robot_T_camera));
  image_t small =
      imageToMessage(cv::Mat(240, 320, CV_8UC3, cv::Scalar::all(90)), 1, f.t_us, f.camera_id);
  EXPECT_FALSE(core->onImage(small).has_value());
  EXPECT_EQ(core->drops().bad_size, 1);
  EXPECT_NE(core->status().message.find("320x240"), std::string::npos);
  EXPECT_NE(core->status().message.find("'" + f.camera_id + "'"), std::string::npos);

  image_t truncated = image;
  truncated.data.resize(1000);
  truncated.size = 1000;
  EXPECT_FALSE(core->onImage(truncated).has_value());
  image_t stranger = image;
  stranger.camera_id = "no-such-camera";
  EXPECT_FALSE(core->onImage(stranger).has_value());
  localization_hint_t hint{};
  hint.kind = 42;
  core->onHint(hint);
  EXPECT_EQ(core->drops().malformed, 5);

  EXPECT_TRUE(core->onImage(image).has_value());   // the good image goes through
  EXPECT_FALSE(core->onImage(image).has_value());  // the same again is old
  EXPECT_EQ(core->drops().old_image, 1);
  EXPECT_EQ(core->status().frames_processed, 1);
  EXPECT_EQ(core->status().dropped_malformed, 5);
}

// A time no clock gives (the node fuzz target's int64 extremes overflowed the gap arithmetic
// of the status message) is refused on every input; the streams keep their sane times.
TEST_F(NodeCoreTest, RefusesTimesNoClockGives) {
  auto core = makeCore();
  const FrameRecord& f = rec_.frames[0];
  const std::int64_t extremes[] = {std::numeric_limits<std::int64_t>::min(), -1,
                                   std::int64_t{1} << 53, std::numeric_limits<std::int64_t>::max()};
  for (const std::int64_t t : extremes) {
    core->onOdometry(odometryToMessage(t, f.odometry.value()));
    core->onCameraPose(cameraPoseToMessage(t, f.camera_id, f.robot_T_camera));
    localization_hint_t hint{};
    hint.utime = t;
    core->onHint(hint);
    EXPECT_FALSE(core->onImage(imageToMessage(cv::Mat(10, 10, CV_8UC3), 0, t, f.camera_id)));
  }
  EXPECT_EQ(core->drops().malformed, 16);
  EXPECT_NE(core->status().message.find("out of range"), std::string::npos);
  // The refused times left no trace: the good frame goes through and the status is finite.
  core->onOdometry(odometryToMessage(f.t_us, f.odometry.value()));
  core->onCameraPose(cameraPoseToMessage(f.t_us, f.camera_id, f.robot_T_camera));
  EXPECT_TRUE(core->onImage(imageMessage(f, 0)).has_value());
  EXPECT_EQ(core->status().message.find("apart"), std::string::npos) << core->status().message;
}

}  // namespace
}  // namespace houghloc
