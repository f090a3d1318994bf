#include "tools/node/node_options.h"

#include <CLI/CLI.hpp>
#include <fstream>
#include <opencv2/core/persistence.hpp>
#include <sstream>
#include <stdexcept>

#include "localization/localizer_config_io.h"
#include "tools/node/node_log.h"
#include "tools/offline/offline_config.h"
#include "vision/vision_config_io.h"

namespace houghloc {
namespace {

/// The keys of `node:` that are flags too: a string or, for repeatable flags, a list of them.
struct FlagKey {
  const char* key;
  std::string NodeOptions::*text = nullptr;
  std::vector<std::string> NodeOptions::*list = nullptr;
};

const FlagKey kFlagKeys[] = {
    {"field", &NodeOptions::field},
    {"standard", &NodeOptions::standard},
    {"camera_yaml", nullptr, &NodeOptions::camera_yaml},
    {"device", nullptr, &NodeOptions::device},
    {"lcm_url", &NodeOptions::lcm_url},
    {"channel_prefix", &NodeOptions::channel_prefix},
    {"save_pose", &NodeOptions::save_pose},
    {"publish_line_points", &NodeOptions::publish_line_points},
    {"log_level", &NodeOptions::log_level},
};

std::string flagOf(const std::string& key) {
  std::string flag = "--" + key;
  for (char& c : flag)
    if (c == '_') c = '-';
  return flag;
}

std::string readText(const cv::FileNode& node, const std::string& where) {
  if (node.isNone()) return "";
  if (!node.isString()) throw std::runtime_error(where + ": expected a string");
  return static_cast<std::string>(node);
}

std::map<std::string, Pose3> readStaticPoses(const cv::FileNode& node, const std::string& where) {
  std::map<std::string, Pose3> poses;
  if (node.isNone()) return poses;
  if (!node.isMap()) throw std::runtime_error(where + ": expected a map camera id: [x, y, z, ...]");
  for (cv::FileNodeIterator it = node.begin(); it != node.end(); ++it) {
    const cv::FileNode pose = *it;
    // OpenCV keeps the quotes of the empty key: "" is the camera with the empty id.
    const std::string id = pose.name() == "\"\"" ? "" : pose.name();
    const std::string at = where + "." + pose.name();
    if (!pose.isSeq() || pose.size() != 6)
      throw std::runtime_error(at + ": expected [x, y, z, roll, pitch, yaw] (m, rad)");
    double v[6];
    for (int i = 0; i < 6; ++i) {
      if (!pose[i].isReal() && !pose[i].isInt())
        throw std::runtime_error(at + ": expected 6 numbers");
      v[i] = static_cast<double>(pose[i]);
    }
    Pose3 p;
    p.x = v[0], p.y = v[1], p.z = v[2], p.roll = v[3], p.pitch = v[4], p.yaw = v[5];
    if (!p.isFinite()) throw std::runtime_error(at + ": not finite");
    poses[id] = p;
  }
  return poses;
}

/// Reads one key into `out`; false when `key` is not a key of the section.
bool readKey(const cv::FileNode& node, const std::string& key, const std::string& where,
             NodeOptions* out) {
  if (key == "static_camera_pose") {
    out->static_camera_pose = readStaticPoses(node, where);
    return true;
  }
  for (const FlagKey& f : kFlagKeys) {
    if (key != f.key) continue;
    if (f.text) {
      out->*f.text = readText(node, where);
    } else if (node.isSeq()) {
      for (cv::FileNodeIterator it = node.begin(); it != node.end(); ++it)
        (out->*f.list).push_back(readText(*it, where));
    } else if (!node.isNone()) {
      (out->*f.list).push_back(readText(node, where));
    }
    return true;
  }
  return false;
}

/// Checks the values; `where` is "FILE: node." for a config section, empty for the command line
/// (whose values are then named by their flags).
void check(const NodeOptions& o, const std::string& where) {
  auto name = [&](const std::string& key) { return where.empty() ? flagOf(key) : where + key; };
  if (o.publish_line_points != "on" && o.publish_line_points != "off")
    throw std::runtime_error(name("publish_line_points") + ": expected on or off, not '" +
                             o.publish_line_points + "'");
  if (!parseLogLevel(o.log_level))
    throw std::runtime_error(name("log_level") + ": expected error, warn, info or debug, not '" +
                             o.log_level + "'");
  for (const std::string& d : o.device) {
    try {
      splitCameraArgument(d, false);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(name("device") + ": " + e.what());
    }
  }
}

}  // namespace

void addNodeOptions(CLI::App& app, NodeOptions* o) {
  app.add_option("--config", o->config,
                 "config file: vision:, global:, tracker:, localizer: and node: (the flags below "
                 "as keys, dashes as underscores; flags win)");
  app.add_flag("--print-config", o->print_config, "write the default config file and exit");
  auto* field = app.add_option("--field", o->field, "field map YAML");
  app.add_option("--standard", o->standard, "standard field (spl, spl2019, kid, adult, msl)")
      ->excludes(field);
  app.add_option("--camera-yaml", o->camera_yaml,
                 "[ID=]camera.yaml, once per camera (no ID: the camera with the empty id)");
  app.add_option("--device", o->device,
                 "ID=/dev/videoN: grab that camera's frames (raw YUYV) instead of <PREFIX>IMAGE");
  app.add_option("--lcm-url", o->lcm_url, "LCM URL (default: LCM_DEFAULT_URL)");
  app.add_option("--channel-prefix", o->channel_prefix, "channel prefix, e.g. NAO3_");
  app.add_option("--save-pose", o->save_pose,
                 "write the best pose to FILE every second; restore it (RESET_TO) at start");
  app.add_option("--publish-line-points", o->publish_line_points, "publish LINE_POINTS (on|off)");
  app.add_option("--log-level", o->log_level, "what to print: error, warn, info or debug");
}

void applyNodeConfig(const CLI::App& app, NodeOptions* o) {
  if (!o->config.empty()) {
    const cv::FileStorage storage = openConfigFile(o->config);
    const cv::FileNode section = storage["node"];
    const std::string where = o->config + ": node";
    if (!section.empty() && !section.isNone() && !section.isMap())
      throw std::runtime_error(where + ": expected a map");
    NodeOptions file;
    if (section.isMap()) {
      for (cv::FileNodeIterator it = section.begin(); it != section.end(); ++it) {
        const cv::FileNode node = *it;
        if (!readKey(node, node.name(), where + "." + node.name(), &file))
          throw std::runtime_error(where + "." + node.name() + ": unknown key");
      }
      check(file, where + ".");
    }
    for (const FlagKey& f : kFlagKeys) {
      if (app.count(flagOf(f.key)) > 0 || section[f.key].empty()) continue;
      if (f.text) o->*f.text = file.*f.text;
      if (f.list) o->*f.list = file.*f.list;
    }
    o->static_camera_pose = file.static_camera_pose;
  }
  check(*o, "");
}

std::map<std::string, Pose3> readStaticCameraPoses(const std::string& config_file) {
  const cv::FileStorage storage = openConfigFile(config_file);
  const cv::FileNode section = storage["node"];
  const std::string where = config_file + ": node";
  if (section.empty() || section.isNone()) return {};
  if (!section.isMap()) throw std::runtime_error(where + ": expected a map");
  return readStaticPoses(section["static_camera_pose"], where + ".static_camera_pose");
}

std::string defaultNodeConfigYaml() {
  cv::FileStorage storage(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  writeVisionConfig(storage, VisionConfig{});
  writeLocalizerConfig(storage, LocalizerConfig{});
  const NodeOptions defaults;
  storage << "node"
          << "{";
  for (const FlagKey& f : kFlagKeys) {
    storage << f.key;
    if (f.text) storage << defaults.*f.text;
    if (f.list)
      storage << "["
              << "]";
  }
  storage << "static_camera_pose"
          << "{"
          << "}";
  storage << "}";
  return storage.releaseAndGetString();
}

std::pair<std::string, std::string> splitCameraArgument(const std::string& argument,
                                                        bool id_optional) {
  const auto eq = argument.find('=');
  if (eq == std::string::npos) {
    if (!id_optional) throw std::runtime_error("'" + argument + "': expected ID=VALUE");
    return {"", argument};
  }
  return {argument.substr(0, eq), argument.substr(eq + 1)};
}

}  // namespace houghloc
