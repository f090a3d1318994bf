// houghloc-node's command line and the config file's node: section (flags win, unknown keys
// are errors naming the key, --print-config round trips), and --log-level's filtering.
#include "tools/node/node_options.h"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tools/node/node_log.h"
#include "tools/offline/offline_config.h"

namespace houghloc {
namespace {

class NodeOptionsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::string(HOUGHLOC_NODE_WORK) + "/options";
    std::filesystem::create_directories(dir_);
  }
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path) << text;
    return path;
  }
  /// Parses `args` as houghloc-node's command line, then applies the config file.
  NodeOptions parse(std::vector<std::string> args) {
    CLI::App app;
    NodeOptions options;
    addNodeOptions(app, &options);
    std::reverse(args.begin(), args.end());
    app.parse(args);
    applyNodeConfig(app, &options);
    return options;
  }
  std::string error(std::vector<std::string> args) {
    try {
      parse(std::move(args));
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }
  std::string dir_;
};

TEST_F(NodeOptionsTest, NodeSectionKeysAreTheFlagsAndFlagsWin) {
  const std::string config = write("node.yaml",
                                   "vision:\n"
                                   "  line_width_m: 0.06\n"
                                   "node:\n"
                                   "  standard: spl\n"
                                   "  camera_yaml: [top=top.yaml, bottom=bottom.yaml]\n"
                                   "  device: top=/dev/video0\n"
                                   "  lcm_url: \"udpm://239.255.76.67:7667?ttl=0\"\n"
                                   "  channel_prefix: NAO3_\n"
                                   "  save_pose: /tmp/pose.yaml\n"
                                   "  publish_line_points: \"off\"\n"
                                   "  log_level: warn\n"
                                   "  static_camera_pose:\n"
                                   "    top: [0.05, 0.0, 0.5, 0.0, 0.3, 0.0]\n"
                                   "    \"\": [0, 0, 1, 0, 0.5, 0]\n");
  const NodeOptions o = parse({"--config", config});
  EXPECT_EQ(o.standard, "spl");
  EXPECT_EQ(o.camera_yaml, (std::vector<std::string>{"top=top.yaml", "bottom=bottom.yaml"}));
  EXPECT_EQ(o.device, (std::vector<std::string>{"top=/dev/video0"}));
  EXPECT_EQ(o.lcm_url, "udpm://239.255.76.67:7667?ttl=0");
  EXPECT_EQ(o.channel_prefix, "NAO3_");
  EXPECT_EQ(o.save_pose, "/tmp/pose.yaml");
  EXPECT_EQ(o.publish_line_points, "off");
  EXPECT_EQ(o.log_level, "warn");
  ASSERT_EQ(o.static_camera_pose.size(), 2u);
  EXPECT_DOUBLE_EQ(o.static_camera_pose.at("top").pitch, 0.3);
  EXPECT_DOUBLE_EQ(o.static_camera_pose.at("top").z, 0.5);
  EXPECT_DOUBLE_EQ(o.static_camera_pose.at("").pitch, 0.5);
  EXPECT_DOUBLE_EQ(loadOfflineConfig(config).vision.line_width_m, 0.06);  // other sections

  const NodeOptions flags = parse({"--config", config, "--camera-yaml", "cam.yaml",
                                   "--channel-prefix", "NAO5_", "--log-level", "debug"});
  EXPECT_EQ(flags.camera_yaml, std::vector<std::string>{"cam.yaml"});
  EXPECT_EQ(flags.channel_prefix, "NAO5_");
  EXPECT_EQ(flags.log_level, "debug");
  EXPECT_EQ(flags.standard, "spl");  // not given as a flag: the file's
}

TEST_F(NodeOptionsTest, BadKeysAndValuesAreNamed) {
  const std::string unknown = write("unknown.yaml", "node:\n  camera_yamls: top.yaml\n");
  EXPECT_EQ(error({"--config", unknown}), unknown + ": node.camera_yamls: unknown key");
  const std::string level = write("level.yaml", "node:\n  log_level: verbose\n");
  EXPECT_EQ(error({"--config", level}),
            level + ": node.log_level: expected error, warn, info or debug, not 'verbose'");
  const std::string pose = write("pose.yaml", "node:\n  static_camera_pose:\n    top: [1, 2]\n");
  EXPECT_EQ(error({"--config", pose}),
            pose + ": node.static_camera_pose.top: expected [x, y, z, roll, pitch, yaw] (m, rad)");
  const std::string type = write("type.yaml", "node:\n  save_pose: 3\n");
  EXPECT_EQ(error({"--config", type}), type + ": node.save_pose: expected a string");
  EXPECT_EQ(error({"--log-level", "loud"}),
            "--log-level: expected error, warn, info or debug, not 'loud'");
  EXPECT_EQ(error({"--device", "/dev/video0"}), "--device: '/dev/video0': expected ID=VALUE");
  const std::string device = write("device.yaml", "node:\n  device: [top=/dev/video0, video1]\n");
  EXPECT_EQ(error({"--config", device}), device + ": node.device: 'video1': expected ID=VALUE");
}

TEST_F(NodeOptionsTest, PrintConfigGivesTheDefaultsBack) {
  const std::string printed = defaultNodeConfigYaml();
  EXPECT_NE(printed.find("node:"), std::string::npos);
  const std::string path = write("printed.yaml", printed);
  const NodeOptions read = parse({"--config", path});
  const NodeOptions defaults;
  EXPECT_EQ(read.publish_line_points, defaults.publish_line_points);
  EXPECT_EQ(read.log_level, defaults.log_level);
  EXPECT_EQ(read.camera_yaml, defaults.camera_yaml);
  EXPECT_EQ(read.device, defaults.device);
  EXPECT_EQ(read.lcm_url, defaults.lcm_url);
  EXPECT_TRUE(read.static_camera_pose.empty());
  EXPECT_EQ(defaultConfigYaml().substr(0, 200), printed.substr(0, 200));  // same other sections
  EXPECT_NO_THROW(loadOfflineConfig(path));
}

TEST(NodeLogTest, LevelFiltersWhatIsPrinted) {
  for (const std::string name : {"error", "warn", "info", "debug"}) {
    std::ostringstream out;
    NodeLog log(*parseLogLevel(name), out);
    log.error("e");
    log.warn("w");
    log.info("i");
    log.debug("d");
    const std::string text = out.str();
    const int level = static_cast<int>(*parseLogLevel(name));
    EXPECT_EQ(text.find("houghloc-node: error: e\n") != std::string::npos, true);
    EXPECT_EQ(text.find("houghloc-node: warn: w\n") != std::string::npos, level >= 1) << name;
    EXPECT_EQ(text.find("houghloc-node: info: i\n") != std::string::npos, level >= 2) << name;
    EXPECT_EQ(text.find("houghloc-node: debug: d\n") != std::string::npos, level >= 3) << name;
  }
  EXPECT_FALSE(parseLogLevel("verbose"));
}

}  // namespace
}  // namespace houghloc
