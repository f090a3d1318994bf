// houghloc-offline --lcm-log on an LCM log written here from houghloc-node's core on a rendered
// NAO folder (two cameras): it processes exactly the images the log answers with HYPOTHESES and
// writes the logged poses (1e-9); a file that is not an LCM log is an error naming it.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <opencv2/imgcodecs.hpp>

#include "tests/tools/offline/offline_cli_fixture.h"
#include "tools/lcm/lcm_log_reader.h"
#include "tools/lcm/message_conversion.h"
#include "tools/node/node_core.h"
#include "tools/offline/estimate_csv.h"
#include "tools/recording/recording.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

const std::string kPrefix = "NAO3_";

class LogWriter {
 public:
  explicit LogWriter(const std::string& path) : file_(path, "w") {}
  template <typename T>
  void write(const std::string& channel, const T& msg, std::int64_t t_us) {
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(msg.getEncodedSize()));
    msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    lcm::LogEvent event;
    event.timestamp = t_us;
    event.channel = channel;
    event.datalen = static_cast<std::int32_t>(bytes.size());
    event.data = bytes.data();
    ASSERT_EQ(file_.writeEvent(&event), 0);
  }
  bool good() const { return file_.good(); }

 private:
  lcm::LogFile file_;
};

class OfflineLcmLog : public ::testing::Test {
 protected:
  void SetUp() override {
    rec_ = readRecording(HOUGHLOC_PLAY_FIXTURE);
    ASSERT_TRUE(rec_.field.has_value());
    ASSERT_GE(rec_.cameras.size(), 2u);  // two camera ids taking turns
    for (const auto& [id, intrinsics] : rec_.cameras) {
      cameras_[id] = intrinsics;
      camera_args_ += " --camera-yaml " + id + "=" + rec_.folder + "/cameras/" + id + ".yaml";
    }
    work_ = fs::path(HOUGHLOC_LCM_LOG_WORK);
    fs::create_directories(work_);
  }

  /// The node's core on the folder, as houghloc-play publishes it (YUYV), with a hint at frame
  /// 12 and every fifth image left unprocessed (as when the node falls behind); everything
  /// logged in arrival order, plus another robot's channels and LINE_POINTS. With
  /// `static_poses`, the core has those (config static_camera_pose) and no CAMERA_POSE is sent.
  void writeLog(const std::string& path, const std::map<std::string, Pose3>& static_poses = {}) {
    NodeCore core(std::make_shared<const FieldModel>(*rec_.field), PipelineConfig{}, cameras_);
    core.setStaticCameraPoses(static_poses, "test");
    LogWriter log(path);
    ASSERT_TRUE(log.good());
    for (std::size_t i = 0; i < rec_.frames.size(); ++i) {
      const FrameRecord& f = rec_.frames[i];
      const odometry_t odometry = odometryToMessage(f.t_us, f.odometry.value());
      core.onOdometry(odometry);
      log.write(kPrefix + "ODOMETRY", odometry, f.t_us);
      if (static_poses.empty()) {
        const camera_pose_t pose = cameraPoseToMessage(f.t_us, f.camera_id, f.robot_T_camera);
        core.onCameraPose(pose);
        log.write(kPrefix + "CAMERA_POSE", pose, f.t_us);
      }
      if (i == 12) {
        LocalizationHint hint;
        hint.kind = HintKind::kAdd;
        hint.t_us = f.t_us;
        GaussianPose p;
        p.mean = Pose2(-rec_.ground_truth[i].field_T_robot.x, -rec_.ground_truth[i].field_T_robot.y,
                       rec_.ground_truth[i].field_T_robot.theta + M_PI);  // the mirror twin
        hint.poses.push_back(p);
        const localization_hint_t msg = hintToMessage(hint);
        core.onHint(msg);
        log.write(kPrefix + "HINT", msg, f.t_us);
      }
      const cv::Mat bgr = cv::imread(rec_.folder + "/" + f.image, cv::IMREAD_COLOR);
      const image_t image = imageToMessage(bgr, image_t::PIXEL_FORMAT_YUYV, f.t_us, f.camera_id);
      log.write(kPrefix + "IMAGE", image, f.t_us);
      log.write("NAO4_IMAGE", image, f.t_us);  // another robot's: ignored
      if (i % 5 != 3) {
        const std::optional<NodeOutput> out = core.onImage(image);
        ASSERT_TRUE(out.has_value()) << "frame " << i << ": " << core.status().message;
        log.write(kPrefix + "HYPOTHESES", out->hypotheses, f.t_us + 5000);
        log.write(kPrefix + "LINE_POINTS", out->line_points, f.t_us + 5000);
        logged_.push_back(out->hypotheses);
      }
      LocalizationEstimate truth;
      truth.hypotheses.push_back({GaussianPose{rec_.ground_truth[i].field_T_robot}, 0, 0});
      log.write(kPrefix + "GROUND_TRUTH", hypothesesToMessage(f.t_us, truth), f.t_us);
    }
    log.write(kPrefix + "STATUS", core.status(), rec_.frames.back().t_us + 6000);
  }

  Recording rec_;
  std::map<std::string, CameraIntrinsics> cameras_;
  std::string camera_args_;
  fs::path work_;
  std::vector<pose_hypotheses_t> logged_;
};

TEST_F(OfflineLcmLog, ReproducesTheLoggedPoses) {
  const std::string log = (work_ / "node.log").string();
  const fs::path out = work_ / "out";
  fs::remove_all(out);
  writeLog(log);
  const std::size_t frames = rec_.frames.size();
  ASSERT_EQ(logged_.size(), frames - frames / 5 - (frames % 5 > 3 ? 1 : 0));

  const RunResult r = run("--lcm-log " + log + " --standard spl" + camera_args_ +
                          " --channel-prefix " + kPrefix + " -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<FrameEstimate> written = readFrameEstimates(out.string());
  ASSERT_EQ(written.size(), logged_.size()) << r.output;
  std::size_t hypotheses = 0;
  for (std::size_t k = 0; k < logged_.size(); ++k) {
    const pose_hypotheses_t& want = logged_[k];
    const FrameEstimate& got = written[k];
    EXPECT_EQ(got.t_us, want.utime) << "row " << k;
    EXPECT_EQ(got.status, trackerStatusName(static_cast<TrackerStatus>(want.status)));
    ASSERT_EQ(got.hypotheses.size(), want.hypotheses.size()) << "row " << k;
    for (std::size_t h = 0; h < want.hypotheses.size(); ++h, ++hypotheses) {
      const pose_hypothesis_t& w = want.hypotheses[h];
      const GaussianPose& g = got.hypotheses[h];
      EXPECT_NEAR(g.mean.x, w.x, 1e-9) << "row " << k << " rank " << h;
      EXPECT_NEAR(g.mean.y, w.y, 1e-9) << "row " << k << " rank " << h;
      EXPECT_NEAR(std::remainder(g.mean.theta - w.theta, 2 * M_PI), 0.0, 1e-9);
      EXPECT_NEAR(g.weight, w.weight, 1e-9);
      for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) EXPECT_NEAR(g.covariance(i, j), w.covariance[3 * i + j], 1e-9);
    }
  }
  EXPECT_GT(hypotheses, logged_.size() / 2);
  EXPECT_NE(r.output.find("max difference to log    0 "), std::string::npos) << r.output;
  // GROUND_TRUTH in the log: the tracking metrics, scored on every processed frame.
  std::ifstream metrics(out / "metrics.json");
  std::stringstream text;
  text << metrics.rdbuf();
  EXPECT_NE(text.str().find("\"frames_scored\": " + std::to_string(logged_.size())),
            std::string::npos)
      << text.str();
  EXPECT_TRUE(fs::exists(out / "trajectory.png"));
}

// A node that ran with `node: static_camera_pose` (no CAMERA_POSE in its log) is replayed with
// the same config file; without it the images have no camera pose and are refused.
TEST_F(OfflineLcmLog, StaticCameraPoseComesFromTheNodeConfig) {
  std::map<std::string, Pose3> poses;
  for (const FrameRecord& f : rec_.frames) poses.emplace(f.camera_id, f.robot_T_camera);
  ASSERT_EQ(poses.size(), cameras_.size());
  const fs::path config = work_ / "static.yaml";
  {
    std::ofstream yaml(config);
    yaml << "%YAML:1.0\nnode:\n  static_camera_pose:\n";
    char line[400];
    for (const auto& [id, p] : poses) {
      std::snprintf(line, sizeof line, "    %s: [%.17g, %.17g, %.17g, %.17g, %.17g, %.17g]\n",
                    id.c_str(), p.x, p.y, p.z, p.roll, p.pitch, p.yaw);
      yaml << line;
    }
  }
  const std::string log = (work_ / "static.log").string();
  writeLog(log, poses);
  const std::string common = "--lcm-log " + log + " --standard spl" + camera_args_ +
                             " --channel-prefix " + kPrefix + " -o ";
  const RunResult with =
      run(common + (work_ / "static_out").string() + " --config " + config.string());
  ASSERT_EQ(with.exit_code, 0) << with.output;
  EXPECT_EQ(readFrameEstimates((work_ / "static_out").string()).size(), logged_.size());
  EXPECT_NE(with.output.find("max difference to log    0 "), std::string::npos) << with.output;

  const RunResult without = run(common + (work_ / "static_out_none").string());
  EXPECT_NE(without.output.find("refused here"), std::string::npos) << without.output;
}

TEST_F(OfflineLcmLog, NamesAFileThatIsNotAnLcmLog) {
  const std::string yaml = rec_.folder + "/cameras/nao-top.yaml";
  const RunResult r = run("--lcm-log " + yaml + " --standard spl" + camera_args_ + " -o " +
                          (work_ / "not_a_log").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(yaml + ": not an LCM log"), std::string::npos) << r.output;

  const RunResult missing =
      run("--lcm-log " + (work_ / "missing.log").string() + " --standard spl" + camera_args_);
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.output.find("missing.log: no such file"), std::string::npos) << missing.output;
}

TEST_F(OfflineLcmLog, ReaderRefusesStrayBytesAndReportsACutTail) {
  const std::string good = (work_ / "small.log").string();
  {
    LogWriter log(good);
    for (int i = 0; i < 3; ++i) log.write("ODOMETRY", odometryToMessage(i, Pose2()), i);
  }
  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::size_t event = bytes.size() / 3;
  auto count = [](const std::string& path) {
    LcmLogReader reader(path);
    int n = 0;
    while (reader.next()) ++n;
    return std::make_pair(n, reader.truncatedAt());
  };
  EXPECT_EQ(count(good), std::make_pair(3, std::int64_t{-1}));

  const std::string stray = (work_ / "stray.log").string();
  std::ofstream(stray, std::ios::binary)
      << bytes.substr(0, 2 * event) << "junk" << bytes.substr(2 * event);
  try {
    count(stray);
    ADD_FAILURE() << "stray bytes were skipped";
  } catch (const LcmLogError& e) {
    EXPECT_NE(std::string(e.what()).find(stray + ": corrupt: no lcm-logger event at byte " +
                                         std::to_string(2 * event)),
              std::string::npos)
        << e.what();
  }
  const std::string cut = (work_ / "cut.log").string();
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() - 5);
  EXPECT_EQ(count(cut), std::make_pair(2, static_cast<std::int64_t>(2 * event)));
}

}  // namespace
}  // namespace houghloc
