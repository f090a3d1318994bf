// houghloc-node: the onboard LCM process (DESIGN §1, §7).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <optional>
#include <string>
#include <thread>

#include "tools/lcm/stop_signal.h"
#include "tools/node/device_grabber.h"
#include "tools/node/node_options.h"
#include "tools/node/node_runner.h"
#include "tools/offline/offline_config.h"
#include "tools/offline/run_field.h"

namespace houghloc {
namespace {

std::map<std::string, CameraIntrinsics> loadCameras(const NodeOptions& o) {
  if (o.camera_yaml.empty()) throw std::runtime_error("give --camera-yaml [ID=]FILE per camera");
  std::map<std::string, CameraIntrinsics> cameras;
  for (const std::string& arg : o.camera_yaml) {
    const auto [id, file] = splitCameraArgument(arg, true);
    cameras[id] = loadCameraYaml(file);
  }
  return cameras;
}

/// The pose saved by an earlier run (--save-pose), read before the map is built so that its
/// problems show at once. A file that is not a saved pose is reported and ignored: the node's
/// own state file must not keep the robot from localizing (it starts as on a first start, and
/// the next save replaces the file).
std::optional<GaussianPose> readSavedPose(const NodeOptions& o, NodeLog& log) {
  if (o.save_pose.empty()) return std::nullopt;
  try {
    std::optional<GaussianPose> pose = loadPoseFile(o.save_pose);
    if (!pose) log.info("no saved pose in " + o.save_pose + " yet");
    return pose;
  } catch (const std::runtime_error& e) {
    log.warn(std::string(e.what()) + "; starting without a saved pose");
    return std::nullopt;
  }
}

void restorePose(GaussianPose pose, const NodeOptions& o, const PoseFileConfig& config,
                 NodeCore& core, NodeLog& log) {
  const double s = config.restore_sigma_m, t = config.restore_sigma_rad;
  pose.covariance = Eigen::Vector3d(s * s, s * s, t * t).asDiagonal();
  core.restorePose(pose);
  char text[200];
  std::snprintf(text, sizeof(text),
                "restored pose %.6f %.6f %.6f from %s (RESET_TO, %.2f m, %.2f rad)", pose.mean.x,
                pose.mean.y, pose.mean.theta, o.save_pose.c_str(), s, t);
  log.info(text);
}

int run(const NodeOptions& o, NodeLog& log, const std::atomic<bool>& stop) {
  // One processing thread, no OpenCV worker pool: its threads spin (sched_yield) after every
  // parallel YUYV conversion, which cost the node about a tenth of its CPU (docs/node.md).
  cv::setNumThreads(0);
  if (o.field.empty() == o.standard.empty())
    throw std::runtime_error("give --field FILE or --standard NAME");
  const FieldModel field = loadRunField(o.field, o.standard);
  const std::map<std::string, CameraIntrinsics> cameras = loadCameras(o);
  const OfflineConfig loaded = loadOfflineConfig(o.config);
  const std::optional<GaussianPose> saved_pose = readSavedPose(o, log);
  PipelineConfig config;
  config.vision = loaded.vision;
  config.localizer = loaded.localizer;
  lcm::LCM lcm(o.lcm_url);
  if (!lcm.good()) throw std::runtime_error("cannot open LCM URL '" + o.lcm_url + "'");
  NodeCore core(std::make_shared<const FieldModel>(field), config, cameras);
  core.setStaticCameraPoses(o.static_camera_pose, o.config);
  NodeRunnerOptions runner_options;
  runner_options.save_pose = o.save_pose;
  runner_options.log = &log;
  if (saved_pose) restorePose(*saved_pose, o, runner_options.pose_file, core, log);
  NodeRunner runner(lcm, core, o.channel_prefix, o.publish_line_points == "on", runner_options);

  std::vector<std::unique_ptr<DeviceGrabber>> grabbers;
  for (const std::string& arg : o.device) {
    const auto [id, path] = splitCameraArgument(arg, false);
    const auto camera = cameras.find(id);
    if (camera == cameras.end())
      throw std::runtime_error("--device " + arg + ": no --camera-yaml for camera '" + id + "'");
    grabbers.push_back(std::make_unique<DeviceGrabber>(
        id, path, camera->second.image_width, camera->second.image_height,
        [&runner](image_t image) { runner.submitImage(std::move(image)); },
        [&runner, id = id](const std::string& problem) {
          runner.setCondition("device " + id, problem);
        },
        &log));
  }
  for (auto& grabber : grabbers) grabber->start();
  log.info("running, " + std::to_string(cameras.size()) + " camera(s), " +
           std::to_string(grabbers.size()) + " device(s)");
  runner.run(stop);
  for (auto& grabber : grabbers) grabber->requestStop();
  // The node ends within 1 s of SIGTERM even when a stalled camera blocks a grab in the driver.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
  bool blocked = false;
  for (auto& grabber : grabbers) {
    while (!grabber->finished() && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    blocked = blocked || !grabber->finished();
  }
  log.info("stopped after " + std::to_string(core.status().frames_processed) + " images, dropped " +
           std::to_string(core.drops().total()));
  if (blocked) {
    log.warn("a device grab is blocked in the driver: exiting without waiting for it");
    std::_Exit(0);
  }
  return 0;
}

}  // namespace
}  // namespace houghloc

int main(int argc, char** argv) {
  using namespace houghloc;
  CLI::App app{
      "houghloc-node: subscribes to <PREFIX>IMAGE (or grabs --device), ODOMETRY, CAMERA_POSE, "
      "HINT and publishes <PREFIX>HYPOTHESES (one per processed image), STATUS (1 Hz and on "
      "state change), LINE_POINTS (docs/node.md, docs/lcm.md)"};
  NodeOptions options;
  addNodeOptions(app, &options);
  CLI11_PARSE(app, argc, argv);
  if (options.print_config) {
    std::cout << defaultNodeConfigYaml();
    return 0;
  }
  try {
    applyNodeConfig(app, &options);
  } catch (const std::exception& e) {
    std::cerr << "houghloc-node: error: " << e.what() << "\n";
    return 1;
  }
  NodeLog log(*parseLogLevel(options.log_level), std::cerr);
  // Before the map is built (~1 s on a loaded robot): a SIGTERM while starting ends it cleanly.
  const std::atomic<bool>& stop = installStopSignals();
  try {
    return run(options, log, stop);
  } catch (const std::exception& e) {
    log.error(e.what());
    return 1;
  }
}
