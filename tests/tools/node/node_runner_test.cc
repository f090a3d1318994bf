// NodeRunner in process over memq:// (its LCM thread and processing thread, as in houghloc-node)
// on the rendered one-camera walk: the same hypotheses as NodeCore fed directly, random bytes on
// every input channel, a device that does not exist, and a restart with --save-pose.
#include "tools/node/node_runner.h"

#include <condition_variable>
#include <filesystem>
#include <random>
#include <sstream>
#include <thread>

#include "tests/tools/node/memq_node.h"
#include "tests/tools/node/node_test_support.h"
#include "tools/node/device_grabber.h"

namespace houghloc {
namespace {

/// A NodeRunner on its own thread and a test-side subscriber on the same memq:// LCM.
class RunningNode {
 public:
  RunningNode(NodeCore& core, const NodeRunnerOptions& options = {}) : node_(core, options) {
    node_.lcm().subscribe("HYPOTHESES", &RunningNode::onHypotheses, this);
    node_.lcm().subscribe("STATUS", &RunningNode::onStatus, this);
    node_.start();
  }
  void stop() { node_.stop(); }

  template <typename T>
  void publish(const std::string& channel, const T& msg) {
    node_.publish(channel, msg);
  }
  void publishRaw(const std::string& channel, const std::vector<std::uint8_t>& bytes) {
    node_.publishRaw(channel, bytes);
  }
  /// The HYPOTHESES of the image stamped `utime`, waiting up to 5 s.
  std::optional<pose_hypotheses_t> waitHypotheses(std::int64_t utime) {
    std::unique_lock<std::mutex> lock(mutex_);
    wake_.wait_for(lock, std::chrono::seconds(5), [&] { return hypotheses_.count(utime) > 0; });
    const auto it = hypotheses_.find(utime);
    if (it == hypotheses_.end()) return std::nullopt;
    return it->second;
  }
  std::vector<localizer_status_t> statuses() {
    std::lock_guard<std::mutex> lock(mutex_);
    return statuses_;
  }
  NodeRunner& runner() { return node_.runner(); }

 private:
  void onHypotheses(const lcm::ReceiveBuffer*, const std::string&, const pose_hypotheses_t* m) {
    std::lock_guard<std::mutex> lock(mutex_);
    hypotheses_[m->utime] = *m;
    wake_.notify_all();
  }
  void onStatus(const lcm::ReceiveBuffer*, const std::string&, const localizer_status_t* m) {
    std::lock_guard<std::mutex> lock(mutex_);
    statuses_.push_back(*m);
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::map<std::int64_t, pose_hypotheses_t> hypotheses_;
  std::vector<localizer_status_t> statuses_;
  MemqNode node_;  ///< last: stopped before the members its handlers touch go
};

class NodeRunnerTest : public NodeFixture {
 protected:
  /// Publishes frame i's odometry, camera pose and image (as houghloc-play does) and waits for
  /// its HYPOTHESES (as houghloc-play --fast does).
  std::optional<pose_hypotheses_t> play(RunningNode& node, std::size_t i) {
    const FrameRecord& f = frame(i);
    node.publish("ODOMETRY", odometryToMessage(f.t_us, f.odometry.value()));
    node.publish("CAMERA_POSE", cameraPoseToMessage(f.t_us, f.camera_id, f.robot_T_camera));
    node.publish("IMAGE", image(i, f.t_us));
    return node.waitHypotheses(f.t_us);
  }
};

TEST_F(NodeRunnerTest, GivesNodeCoresHypothesesOverMemq) {
  auto core = makeCore(), reference = makeCore();
  RunningNode node(*core);
  std::map<std::size_t, pose_hypotheses_t> results;
  for (std::size_t i = 0; i < frames(); ++i) {
    const std::optional<pose_hypotheses_t> h = play(node, i);
    ASSERT_TRUE(h) << "no HYPOTHESES for frame " << i;
    results[i] = *h;
    const FrameRecord& f = frame(i);
    reference->onOdometry(odometryToMessage(f.t_us, f.odometry.value()));
    reference->onCameraPose(cameraPoseToMessage(f.t_us, f.camera_id, f.robot_T_camera));
    const std::optional<NodeOutput> direct = reference->onImage(image(i, f.t_us));
    ASSERT_TRUE(direct);
    ASSERT_EQ(h->num_hypotheses, direct->hypotheses.num_hypotheses) << "frame " << i;
    for (int k = 0; k < h->num_hypotheses; ++k) {
      EXPECT_EQ(h->hypotheses[k].x, direct->hypotheses.hypotheses[k].x) << "frame " << i;
      EXPECT_EQ(h->hypotheses[k].y, direct->hypotheses.hypotheses[k].y) << "frame " << i;
      EXPECT_EQ(h->hypotheses[k].theta, direct->hypotheses.hypotheses[k].theta) << "frame " << i;
    }
  }
  node.stop();
  EXPECT_GE(shareCorrect(results), 0.95);
  EXPECT_EQ(core->drops().total(), 0);
  const std::vector<localizer_status_t> statuses = node.statuses();
  ASSERT_FALSE(statuses.empty());
  EXPECT_LE(statuses.back().frames_processed, static_cast<std::int64_t>(frames()));
}

TEST_F(NodeRunnerTest, RandomBytesOnEveryInputChannelAreCountedAndIgnored) {
  auto core = makeCore();
  RunningNode node(*core);
  std::mt19937 rng(1717);
  const std::vector<std::string> channels = {"IMAGE", "ODOMETRY", "CAMERA_POSE", "HINT"};
  std::int64_t garbage = 0;
  std::map<std::size_t, pose_hypotheses_t> results;
  for (std::size_t i = 0; i < frames(); ++i) {
    for (const std::string& channel : channels) {
      std::vector<std::uint8_t> bytes(std::uniform_int_distribution<int>(1, 3000)(rng));
      for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
      node.publishRaw(channel, bytes);
      ++garbage;
    }
    if (i % 10 == 0) {  // truncated and wrong-type messages too
      const image_t whole = image(i, frame(i).t_us);
      std::vector<std::uint8_t> bytes(whole.getEncodedSize());
      whole.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
      bytes.resize(bytes.size() / 2);
      node.publishRaw("IMAGE", bytes);
      node.publish("ODOMETRY", cameraPoseToMessage(1, "", frame(i).robot_T_camera));
      garbage += 2;
    }
    const std::optional<pose_hypotheses_t> h = play(node, i);
    ASSERT_TRUE(h) << "no HYPOTHESES for frame " << i;
    results[i] = *h;
  }
  node.stop();
  EXPECT_EQ(core->drops().malformed, garbage);
  EXPECT_EQ(core->drops().total(), garbage);
  EXPECT_EQ(core->status().frames_processed, static_cast<std::int64_t>(frames()));
  EXPECT_GE(shareCorrect(results), 0.95);
  ASSERT_FALSE(node.statuses().empty());
  EXPECT_GT(node.statuses().back().dropped_malformed, 0);
}

TEST_F(NodeRunnerTest, MissingDeviceIsRetriedAndNamedInTheStatus) {
  auto core = makeCore();
  RunningNode node(*core);
  const std::string device = "/dev/houghloc-no-such-video7";
  std::ostringstream printed;
  NodeLog log(LogLevel::kDebug, printed);
  DeviceGrabberConfig config;
  config.retry_s = 0.2;
  int images = 0;
  DeviceGrabber grabber(
      "top", device, 640, 480, [&images](image_t) { ++images; },
      [&node](const std::string& problem) { node.runner().setCondition("device top", problem); },
      &log, config);
  grabber.start();
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  EXPECT_GE(grabber.attempts(), 4);  // once at start, then every 0.2 s
  grabber.requestStop();             // ends a wait to retry at once (houghloc-node waits <= 0.5 s)
  const auto asked = std::chrono::steady_clock::now();
  while (!grabber.finished() && std::chrono::steady_clock::now() - asked < std::chrono::seconds(1))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_LT(std::chrono::steady_clock::now() - asked, std::chrono::milliseconds(500));
  grabber.stop();
  node.stop();
  EXPECT_EQ(images, 0);
  const std::string expected = "camera 'top': " + device + " does not exist; retrying every 0.2 s";
  bool in_status = false;
  for (const localizer_status_t& s : node.statuses())
    in_status = in_status || s.message.find(expected) != std::string::npos;
  EXPECT_TRUE(in_status) << "no STATUS names the missing device";
  // Printed once as a warning, each retry at debug level.
  const std::string text = printed.str();
  EXPECT_NE(text.find("houghloc-node: warn: " + expected), std::string::npos) << text;
  EXPECT_NE(text.find("houghloc-node: debug: " + expected), std::string::npos) << text;
  EXPECT_EQ(text.find("warn:"), text.rfind("warn:")) << text;
}

TEST_F(NodeRunnerTest, RestartWithSavePoseContinuesTracking) {
  const std::string dir = std::string(HOUGHLOC_NODE_WORK) + "/save_pose";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  NodeRunnerOptions options;
  options.save_pose = dir + "/pose.yaml";
  options.pose_file.save_period_s = 0.2;
  const std::size_t restart = 150;
  GaussianPose last;
  {
    auto core = makeCore();
    RunningNode node(*core, options);
    for (std::size_t i = 0; i < restart; ++i) ASSERT_TRUE(play(node, i)) << "frame " << i;
    EXPECT_TRUE(std::filesystem::exists(options.save_pose));  // saved while running
    node.stop();                                              // and once more at the end
    // The SPL field is point-symmetric and the walk has no hints: both twins are tracked
    // (AMBIGUOUS), the best one is saved.
    ASSERT_EQ(core->estimate().status, TrackerStatus::kAmbiguous);
    last = *core->estimate().best();
  }
  const std::optional<GaussianPose> saved = loadPoseFile(options.save_pose);
  ASSERT_TRUE(saved);
  EXPECT_NEAR(saved->mean.x, last.mean.x, 1e-12);
  EXPECT_NEAR(saved->mean.y, last.mean.y, 1e-12);
  EXPECT_NEAR(saved->mean.theta, last.mean.theta, 1e-12);
  EXPECT_FALSE(std::filesystem::exists(options.save_pose + ".tmp"));

  // The next start: the saved pose as a RESET_TO hint, then the rest of the walk.
  auto core = makeCore();
  GaussianPose hint = *saved;
  const double s = options.pose_file.restore_sigma_m, t = options.pose_file.restore_sigma_rad;
  hint.covariance = Eigen::Vector3d(s * s, s * s, t * t).asDiagonal();
  core->restorePose(hint);
  RunningNode node(*core, options);
  std::map<std::size_t, pose_hypotheses_t> results;
  for (std::size_t i = restart; i < frames(); ++i) {
    const std::optional<pose_hypotheses_t> h = play(node, i);
    ASSERT_TRUE(h) << "frame " << i;
    results[i] = *h;
  }
  node.stop();
  // Tracking from the first image on (no global relocalisation, no wrong half).
  EXPECT_EQ(results.begin()->second.status, +pose_hypotheses_t::TRACKING);
  std::size_t first = 0;
  EXPECT_GE(shareCorrect(results, &first), 0.95);
  EXPECT_EQ(first, restart);
  // Without the saved pose the same first image leaves the node without one pose.
  auto fresh = makeCore();
  fresh->onOdometry(odometryToMessage(frame(restart).t_us, frame(restart).odometry.value()));
  fresh->onCameraPose(cameraPoseToMessage(frame(restart).t_us, frame(restart).camera_id,
                                          frame(restart).robot_T_camera));
  const auto alone = fresh->onImage(image(restart, frame(restart).t_us));
  ASSERT_TRUE(alone);
  EXPECT_NE(alone->hypotheses.status, +pose_hypotheses_t::TRACKING);
}

}  // namespace
}  // namespace houghloc
