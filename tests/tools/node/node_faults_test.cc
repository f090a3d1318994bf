// houghloc-node's faults that need no second process, driven through NodeCore on the rendered
// one-camera walk (10 s, 30 Hz) and scored against its ground truth: a publisher whose clock
// restarts, odometry missing for 2 s, camera poses missing, a static camera pose, and the
// saved pose file.
#include <filesystem>
#include <fstream>

#include "tests/tools/node/node_test_support.h"
#include "tools/node/pose_file.h"

namespace houghloc {
namespace {

class NodeFaultsTest : public NodeFixture {
 protected:
  /// Feeds frame i (odometry, camera pose, image) stamped `utime`; returns its hypotheses.
  std::optional<pose_hypotheses_t> feed(NodeCore& core, std::size_t i, std::int64_t utime,
                                        bool odometry = true, bool camera_pose = true,
                                        const Pose2* odometry_value = nullptr) {
    const FrameRecord& f = frame(i);
    if (odometry)
      core.onOdometry(
          odometryToMessage(utime, odometry_value ? *odometry_value : f.odometry.value()));
    if (camera_pose) core.onCameraPose(cameraPoseToMessage(utime, f.camera_id, f.robot_T_camera));
    const std::optional<NodeOutput> out = core.onImage(image(i, utime));
    if (!out) return std::nullopt;
    EXPECT_EQ(out->hypotheses.utime, utime);
    return out->hypotheses;
  }
};

TEST_F(NodeFaultsTest, PublisherRestartedMidRunKeepsTracking) {
  auto core = makeCore();
  const std::size_t restart = frames() / 2;
  // The restarted publisher's clock and cumulative odometry both start again from zero.
  const std::int64_t back = frame(restart).t_us - 1'000'000;
  const Pose2 odometry_origin = frame(restart).odometry.value();
  std::map<std::size_t, pose_hypotheses_t> before, after;
  for (std::size_t i = 0; i < frames(); ++i) {
    if (i < restart) {
      const auto h = feed(*core, i, frame(i).t_us);
      ASSERT_TRUE(h) << "frame " << i << ": " << core->status().message;
      before[i] = *h;
    } else {
      const Pose2 odometry = odometry_origin.inverse() * frame(i).odometry.value();
      const auto h = feed(*core, i, frame(i).t_us - back, true, true, &odometry);
      ASSERT_TRUE(h) << "frame " << i << ": " << core->status().message;
      after[i] = *h;
    }
  }
  EXPECT_EQ(core->restarts(), 1);
  EXPECT_EQ(core->drops().total(), 0);
  EXPECT_NE(core->status().message.find("publisher restarted"), std::string::npos)
      << core->status().message;
  EXPECT_GE(shareCorrect(before), 0.95);
  std::size_t first = 0;
  EXPECT_GE(shareCorrect(after, &first), 0.95);
  EXPECT_LE(first, restart + 2) << "tracking did not continue across the restart";
  // A step back within restart_gap_us is an old image, not a restart.
  EXPECT_FALSE(feed(*core, frames() - 1, frame(frames() - 1).t_us - back - 500'000));
  EXPECT_EQ(core->drops().old_image, 1);
  EXPECT_EQ(core->restarts(), 1);
}

TEST_F(NodeFaultsTest, OdometryMissingForTwoSeconds) {
  auto core = makeCore();
  const std::size_t gap_begin = 100, gap_end = 160;  // 60 frames at 30 Hz: 2 s
  std::map<std::size_t, pose_hypotheses_t> results;
  for (std::size_t i = 0; i < frames(); ++i) {
    const bool odometry = i < gap_begin || i >= gap_end;
    const auto h = feed(*core, i, frame(i).t_us, odometry);
    ASSERT_TRUE(h) << "frame " << i << ": " << core->status().message;
    results[i] = *h;
    const std::int64_t since = frame(i).t_us - frame(gap_begin - 1).t_us;
    const bool reported = core->status().message.find("odometry") != std::string::npos;
    if (!odometry && since > 1'050'000) {
      EXPECT_TRUE(reported) << "frame " << i;
    }
    if (odometry || since < 950'000) {
      EXPECT_FALSE(reported) << "frame " << i;
    }
  }
  EXPECT_EQ(core->drops().total(), 0);
  EXPECT_GE(shareCorrect(results), 0.95);
  std::map<std::size_t, pose_hypotheses_t> after(results.find(gap_end), results.end());
  std::size_t first = 0;
  EXPECT_GE(shareCorrect(after, &first), 0.95);
  EXPECT_EQ(first, gap_end);
}

TEST_F(NodeFaultsTest, CameraPosesMissingDropsAndCountsImages) {
  auto core = makeCore();
  const std::size_t gap_begin = 100, gap_end = 140;
  // Reference: an image is usable while the last camera pose (frame gap_begin - 1) is within
  // 50 ms of it, then dropped until camera poses come back.
  int expected_drops = 0;
  for (std::size_t i = gap_begin; i < gap_end; ++i)
    expected_drops += frame(i).t_us - frame(gap_begin - 1).t_us > 50'000;
  ASSERT_GT(expected_drops, 30);
  std::map<std::size_t, pose_hypotheses_t> results;
  for (std::size_t i = 0; i < frames(); ++i) {
    const bool pose = i < gap_begin || i >= gap_end;
    const auto h = feed(*core, i, frame(i).t_us, true, pose);
    if (h) results[i] = *h;
    const std::string message = core->status().message;
    if (!pose && frame(i).t_us - frame(gap_begin - 1).t_us > 50'000) {
      EXPECT_FALSE(h) << "frame " << i;
      EXPECT_NE(message.find("no camera pose within 50 ms"), std::string::npos) << message;
    }
    if (!pose && frame(i).t_us - frame(gap_begin - 1).t_us > 1'050'000) {
      EXPECT_NE(message.find("camera poses"), std::string::npos) << message;
    }
    if (i > gap_end + 40) {
      EXPECT_EQ(message, "") << "frame " << i;
    }
  }
  EXPECT_EQ(core->drops().no_camera_pose, expected_drops);
  EXPECT_EQ(core->status().dropped_no_camera_pose, expected_drops);
  EXPECT_EQ(core->drops().total(), expected_drops);
  EXPECT_EQ(results.size(), frames() - expected_drops);
  EXPECT_GE(shareCorrect(results), 0.95);
}

TEST_F(NodeFaultsTest, StaticCameraPoseStandsInForCameraPoseMessages) {
  // Reference: the same pose sent as camera_pose_t with every image.
  const Pose3 fixed = frame(0).robot_T_camera;
  auto with_static = makeCore(), with_messages = makeCore();
  with_static->setStaticCameraPose(frame(0).camera_id, fixed);
  const std::size_t n = 90;
  for (std::size_t i = 0; i < n; ++i) {
    const FrameRecord& f = frame(i);
    with_static->onOdometry(odometryToMessage(f.t_us, f.odometry.value()));
    with_messages->onOdometry(odometryToMessage(f.t_us, f.odometry.value()));
    with_messages->onCameraPose(cameraPoseToMessage(f.t_us, f.camera_id, fixed));
    const image_t msg = image(i, f.t_us);
    const auto a = with_static->onImage(msg), b = with_messages->onImage(msg);
    ASSERT_TRUE(a && b) << "frame " << i << ": " << with_static->status().message;
    ASSERT_EQ(a->hypotheses.num_hypotheses, b->hypotheses.num_hypotheses) << "frame " << i;
    for (int k = 0; k < a->hypotheses.num_hypotheses; ++k) {
      EXPECT_EQ(a->hypotheses.hypotheses[k].x, b->hypotheses.hypotheses[k].x);
      EXPECT_EQ(a->hypotheses.hypotheses[k].theta, b->hypotheses.hypotheses[k].theta);
    }
  }
  EXPECT_EQ(with_static->drops().total(), 0);
  EXPECT_EQ(with_static->status().frames_processed, static_cast<std::int64_t>(n));
  // Without it the same images are dropped for want of a camera pose.
  auto without = makeCore();
  EXPECT_FALSE(without->onImage(image(0, frame(0).t_us)));
  EXPECT_EQ(without->drops().no_camera_pose, 1);
}

TEST_F(NodeFaultsTest, CameraStreamsMoreThanOneSecondApartAreReported) {
  // A second camera ("bottom", the same images) that stops after the first frame.
  std::map<std::string, CameraIntrinsics> two = cameras_;
  two["bottom"] = cameras_.begin()->second;
  NodeCore core(std::make_shared<const FieldModel>(*rec_->field), PipelineConfig{}, two);
  const std::string top = frame(0).camera_id;
  for (std::size_t i = 0; i < 45; ++i) {
    const FrameRecord& f = frame(i);
    core.onOdometry(odometryToMessage(f.t_us, f.odometry.value()));
    for (const std::string& id : {top, std::string("bottom")}) {
      if (id == "bottom" && i > 0) continue;
      core.onCameraPose(cameraPoseToMessage(f.t_us, id, f.robot_T_camera));
      image_t msg = image(i, f.t_us);
      msg.camera_id = id;
      ASSERT_TRUE(core.onImage(msg)) << "frame " << i << ": " << core.status().message;
    }
    const std::int64_t behind = f.t_us - frame(0).t_us;
    const std::string message = core.status().message;
    const bool reported = message.find("camera 'bottom': images ") != std::string::npos &&
                          message.find(" s behind camera '" + top + "'") != std::string::npos;
    EXPECT_EQ(reported, behind > 1'000'000) << "frame " << i << ": " << message;
  }
}

TEST_F(NodeFaultsTest, PoseFileIsWrittenAtomicallyAndReadBack) {
  const std::string dir = std::string(HOUGHLOC_NODE_WORK) + "/pose_file";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/pose.yaml";
  EXPECT_FALSE(loadPoseFile(path));  // the first start
  GaussianPose pose;
  pose.mean = Pose2(1.234567890123, -2.5, 2.9);
  pose.covariance << 0.01, 0.002, 0.0, 0.002, 0.02, 0.001, 0.0, 0.001, 0.003;
  savePoseFile(path, pose);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  const std::optional<GaussianPose> back = loadPoseFile(path);
  ASSERT_TRUE(back);
  EXPECT_NEAR(back->mean.x, pose.mean.x, 1e-12);
  EXPECT_NEAR(back->mean.y, pose.mean.y, 1e-12);
  EXPECT_NEAR(back->mean.theta, pose.mean.theta, 1e-12);
  EXPECT_LT((back->covariance - pose.covariance).cwiseAbs().maxCoeff(), 1e-15);
  // A write that fails (the temporary file's place is taken) leaves the old file whole.
  std::filesystem::create_directory(path + ".tmp");
  GaussianPose other = pose;
  other.mean.x = 0.0;
  EXPECT_THROW(savePoseFile(path, other), std::runtime_error);
  EXPECT_NEAR(loadPoseFile(path)->mean.x, pose.mean.x, 1e-12);
  std::ofstream(dir + "/bad.yaml") << "x: 1\ny: 2\n";
  try {
    loadPoseFile(dir + "/bad.yaml");
    ADD_FAILURE() << "no error for a file without theta";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.yaml: theta"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace houghloc
