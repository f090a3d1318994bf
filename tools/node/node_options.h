#pragma once

#include <map>
#include <string>
#include <vector>

#include "field_models/pose3.h"

namespace CLI {
class App;
}

namespace houghloc {

/// houghloc-node's command line. Each flag is also a key of the config file's `node:` section,
/// named like the flag with underscores (--camera-yaml: camera_yaml); a flag given on the command
/// line wins over its key. static_camera_pose exists in the file only.
struct NodeOptions {
  std::string config;  ///< --config: the file with vision:, global:, ..., node:
  bool print_config = false;
  std::string field, standard;
  std::vector<std::string> camera_yaml;  ///< [ID=]FILE; no ID: the camera with the empty id
  std::vector<std::string> device;       ///< ID=/dev/videoN, grabbed with cv::VideoCapture
  std::string lcm_url;                   ///< empty: LCM_DEFAULT_URL
  std::string channel_prefix;
  std::string save_pose;  ///< file for the best pose, written every second, restored at start
  std::string publish_line_points = "on";  ///< on | off
  std::string log_level = "info";          ///< error | warn | info | debug
  /// node: static_camera_pose: ID: [x, y, z, roll, pitch, yaw] (m, rad): robot_T_camera of a
  /// camera on a robot without head joints, used while no camera_pose_t of that camera is near.
  std::map<std::string, Pose3> static_camera_pose;
};

/// Declares every flag of NodeOptions on `app`.
void addNodeOptions(CLI::App& app, NodeOptions* options);

/// Reads the `node:` section of `options->config` (when set) into the options the command line
/// of `app` did not give, then checks the values. Throws std::runtime_error naming the file and
/// key at fault ("houghloc.yaml: node.foo: unknown key").
void applyNodeConfig(const CLI::App& app, NodeOptions* options);

/// The `node: static_camera_pose` map of a config file (empty without the key): what
/// houghloc-offline --lcm-log needs to replay a node that ran with it. Throws like
/// applyNodeConfig().
std::map<std::string, Pose3> readStaticCameraPoses(const std::string& config_file);

/// Every section's defaults (vision:, global:, tracker:, localizer:, node:) as a config file;
/// applyNodeConfig() and loadOfflineConfig() of it give the defaults back.
std::string defaultNodeConfigYaml();

/// "ID=VALUE" to (ID, VALUE); without '=' the id is empty when `id_optional`, else an error.
std::pair<std::string, std::string> splitCameraArgument(const std::string& argument,
                                                        bool id_optional);

}  // namespace houghloc
