// Scenario YAML schema (docs/render.md): one reader per config struct, keys = member names.
#include <cmath>
#include <fstream>
#include <opencv2/core.hpp>
#include <stdexcept>

#include "field_models/angles.h"
#include "field_models/yaml_precheck.h"
#include "tools/render/faults.h"
#include "tools/render/scenario.h"
#include "tools/render/yaml_map.h"

namespace houghloc {
namespace {

/// A sequence of numbers of length min_size..max_size.
std::vector<double> numbers(const cv::FileNode& node, const std::string& name, size_t min_size,
                            size_t max_size) {
  if (!node.isSeq() || node.size() < min_size || node.size() > max_size) {
    throw std::runtime_error(name + ": expected a list of " + std::to_string(min_size) +
                             (max_size > min_size ? " to " + std::to_string(max_size) : "") +
                             " numbers");
  }
  std::vector<double> out;
  for (size_t i = 0; i < node.size(); ++i)
    out.push_back(yamlNumber(node[static_cast<int>(i)], name));
  return out;
}

/// [x, y, theta_deg] -> Pose2.
Pose2 pose2(const cv::FileNode& node, const std::string& name) {
  const std::vector<double> v = numbers(node, name, 3, 3);
  return Pose2(v[0], v[1], v[2] * kDeg);
}

/// Calls fn(YamlMap&) for every element of a sequence of mappings under `key`.
template <typename Fn>
void forEachMap(YamlMap& parent, const char* key, Fn fn) {
  const cv::FileNode seq = parent.child(key);
  if (seq.empty()) return;
  if (!seq.isSeq()) throw std::runtime_error(parent.name(key) + ": expected a list");
  for (int i = 0; i < static_cast<int>(seq.size()); ++i) {
    YamlMap item(seq[i], parent.where(), parent.childPath(key) + "[" + std::to_string(i) + "]");
    fn(item);
    item.finish();
  }
}

Pose3 readPose3(YamlMap& m) {
  Pose3 p;
  double roll = 0, pitch = 0, yaw = 0;
  m.read("x_m", p.x);
  m.read("y_m", p.y);
  m.read("z_m", p.z);
  m.read("roll_deg", roll);
  m.read("pitch_deg", pitch);
  m.read("yaw_deg", yaw);
  p.roll = roll * kDeg;
  p.pitch = pitch * kDeg;
  p.yaw = yaw * kDeg;
  return p;
}

void readTrajectory(YamlMap& top, TrajectoryConfig& t) {
  const cv::FileNode node = top.child("trajectory");
  if (node.empty()) return;
  if (node.isString()) {
    t.name = static_cast<std::string>(node);
    return;
  }
  YamlMap m(node, top.where(), "trajectory");
  m.read("name", t.name);
  const cv::FileNode wps = m.child("waypoints");
  if (!wps.empty()) {
    if (!wps.isSeq()) throw std::runtime_error(m.name("waypoints") + ": expected a list");
    for (int i = 0; i < static_cast<int>(wps.size()); ++i) {
      const auto v = numbers(wps[i], m.name("waypoints") + "[" + std::to_string(i) + "]", 3, 4);
      t.waypoints.push_back(Waypoint{v[0], v[1], v[2], v.size() > 3 ? v[3] : 0.25});
    }
    if (!m.has("name")) t.name = "waypoints";
  }
  m.read("loop", t.loop);
  m.read("walk_speed_mps", t.walk_speed_mps);
  m.read("turn_speed_dps", t.turn_speed_dps);
  m.read("spin_rate_dps", t.spin_rate_dps);
  m.read("spin_x_m", t.spin_x_m);
  m.read("spin_y_m", t.spin_y_m);
  m.read("gait_sway_deg", t.gait_sway_deg);
  m.read("gait_frequency_hz", t.gait_frequency_hz);
  m.read("random_margin_m", t.random_margin_m);
  m.finish();
}

void readHead(YamlMap& m, HeadConfig& h) {
  m.read("mode", h.mode);
  m.read("pan_deg", h.pan_deg);
  m.read("tilt_deg", h.tilt_deg);
  m.read("sweep_amplitude_deg", h.sweep_amplitude_deg);
  m.read("sweep_period_s", h.sweep_period_s);
  m.read("neck_height_below_camera_m", h.neck_height_below_camera_m);
  const cv::FileNode keys = m.child("schedule");
  if (!keys.empty()) {
    if (!keys.isSeq()) throw std::runtime_error(m.name("schedule") + ": expected a list");
    for (int i = 0; i < static_cast<int>(keys.size()); ++i) {
      const auto v = numbers(keys[i], m.name("schedule") + "[" + std::to_string(i) + "]", 3, 3);
      h.schedule.push_back(HeadKey{v[0], v[1], v[2]});
    }
    if (!m.has("mode")) h.mode = "schedule";
  }
}

void readOdometry(YamlMap& m, OdometryConfig& o) {
  m.read("translation_noise", o.translation_noise);
  m.read("rotation_noise", o.rotation_noise);
  m.read("rotation_per_metre_noise_deg", o.rotation_per_metre_noise_deg);
  m.read("scale_bias", o.scale_bias);
  m.read("rotation_bias", o.rotation_bias);
  m.read("slip_rate_hz", o.slip_rate_hz);
  m.read("slip_duration_s", o.slip_duration_s);
  m.read("slip_factor", o.slip_factor);
}

/// [b, g, r] when `key` is present.
void readColour(YamlMap& m, const char* key, std::array<double, 3>& bgr) {
  const cv::FileNode node = m.child(key);
  if (node.empty()) return;
  const std::vector<double> v = numbers(node, m.name(key), 3, 3);
  bgr = {v[0], v[1], v[2]};
}

void readScene(YamlMap& m, SceneConfig& s) {
  m.read("turf_texture", s.turf_texture);
  m.read("mowing_stripes", s.mowing_stripes);
  m.read("stripe_width_m", s.stripe_width_m);
  m.read("stripe_contrast", s.stripe_contrast);
  m.read("lighting_gradient", s.lighting_gradient);
  m.read("lighting_strength", s.lighting_strength);
  m.read("line_wear", s.line_wear);
  m.read("line_edge_roughness_m", s.line_edge_roughness_m);
  m.read("goals", s.goals);
  m.read("goal_nets", s.goal_nets);
  m.read("goal_frame", s.goal_frame);
  m.read("gym_floor", s.gym_floor);
  m.read("court_lines", s.court_lines);
  m.read("walls", s.walls);
  m.read("people", s.people);
  m.read("own_feet", s.own_feet);
  m.read("shadows", s.shadows);
  m.read("room_margin_m", s.room_margin_m);
  m.read("robot_height_m", s.robot_height_m);
  m.read("random_robots", s.random_robots);
  readColour(m, "turf_bgr", s.turf_bgr);
  readColour(m, "paint_bgr", s.paint_bgr);
  m.read("hall_brightness", s.hall_brightness);
}

void readLightChange(YamlMap& m, LightChange& l) {
  m.read("t_s", l.t_s);
  m.read("exposure", l.exposure);
  m.read("color_temperature_k", l.color_temperature_k);
  m.read("ramp_s", l.ramp_s);
}

void readSensor(YamlMap& m, SensorConfig& s) {
  m.read("exposure", s.exposure);
  m.read("color_temperature_k", s.color_temperature_k);
  m.read("tint", s.tint);
  forEachMap(m, "light_changes", [&](YamlMap& item) {
    LightChange l;
    readLightChange(item, l);
    s.light_changes.push_back(l);
  });
  m.read("vignetting", s.vignetting);
  m.read("optics_blur_px", s.optics_blur_px);
  m.read("motion_blur", s.motion_blur);
  m.read("exposure_time_ms", s.exposure_time_ms);
  m.read("noise_sigma", s.noise_sigma);
  m.read("shot_noise", s.shot_noise);
  m.read("yuv422", s.yuv422);
  m.read("supersampling", s.supersampling);
  m.read("image_format", s.image_format);
  m.read("jpeg_quality", s.jpeg_quality);
}

/// Reads an optional sub-mapping `key` with fn(YamlMap&).
template <typename Fn>
void section(YamlMap& top, const char* key, Fn fn) {
  const cv::FileNode node = top.child(key);
  if (node.empty()) return;
  YamlMap m(node, top.where(), top.childPath(key));
  fn(m);
  m.finish();
}

}  // namespace

namespace {

Scenario readScenarioFile(const std::string& path) {
  if (!std::ifstream(path)) throw std::runtime_error(path + ": cannot open scenario file");
  std::string text = readTextFile(path);
  checkYamlBeforeFileStorage(text, path);  // FileStorage hangs on some malformed YAML
  // Like the offline config: a hand-written file without the "%YAML:1.0" line is accepted too.
  if (text.find_first_not_of(" \t\r\n") != std::string::npos && text.rfind("%YAML", 0) != 0) {
    text = "%YAML:1.0\n---\n" + text;
  }
  cv::FileStorage fs;
  try {
    fs.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  } catch (const cv::Exception& e) {
    throw std::runtime_error(path + ": cannot parse scenario (" + e.err + ")");
  }
  if (!fs.isOpened()) throw std::runtime_error(path + ": cannot open scenario file");
  Scenario s;
  YamlMap top(fs.root(), path, "");
  top.read("fps", s.fps);
  top.read("frames", s.frames);
  int seed = static_cast<int>(s.seed);
  top.read("seed", seed);
  s.seed = static_cast<std::uint32_t>(seed);
  top.read("field", s.field);
  top.read("camera", s.camera);
  section(top, "camera_mount", [&](YamlMap& m) { s.camera_mount = readPose3(m); });
  readTrajectory(top, s.trajectory);
  section(top, "head", [&](YamlMap& m) { readHead(m, s.head); });
  forEachMap(top, "kidnaps", [&](YamlMap& m) {
    KidnapConfig k;
    m.read("t_s", k.t_s);
    const cv::FileNode to = m.child("to");
    if (!to.empty()) k.to = pose2(to, m.name("to"));
    s.kidnaps.push_back(k);
  });
  forEachMap(top, "falls", [&](YamlMap& m) {
    FallConfig f;
    m.read("t_s", f.t_s);
    m.read("duration_s", f.duration_s);
    s.falls.push_back(f);
  });
  section(top, "odometry", [&](YamlMap& m) { readOdometry(m, s.odometry); });
  forEachMap(top, "robots", [&](YamlMap& m) {
    RobotConfig r;
    m.read("x_m", r.x_m);
    m.read("y_m", r.y_m);
    m.read("theta_deg", r.theta_deg);
    m.read("team", r.team);
    m.read("vx_mps", r.vx_mps);
    m.read("vy_mps", r.vy_mps);
    s.robots.push_back(r);
  });
  section(top, "ball", [&](YamlMap& m) {
    m.read("enabled", s.ball.enabled);
    double x = 0.0, y = 0.0;
    if (m.has("x_m")) {
      m.read("x_m", x);
      s.ball.x_m = x;
    }
    if (m.has("y_m")) {
      m.read("y_m", y);
      s.ball.y_m = y;
    }
    m.read("vx_mps", s.ball.vx_mps);
    m.read("vy_mps", s.ball.vy_mps);
    m.read("diameter_m", s.ball.diameter_m);
  });
  section(top, "scene", [&](YamlMap& m) { readScene(m, s.scene); });
  section(top, "sensor", [&](YamlMap& m) { readSensor(m, s.sensor); });
  section(top, "camera_pose_error", [&](YamlMap& m) {
    const cv::FileNode bias = m.child("bias");
    if (!bias.empty()) {
      YamlMap b(bias, m.where(), m.childPath("bias"));
      s.camera_pose_error.bias = readPose3(b);
      b.finish();
    }
    m.read("noise_deg", s.camera_pose_error.noise_deg);
  });
  forEachMap(top, "hints", [&](YamlMap& m) {
    HintConfig h;
    m.read("t_s", h.t_s);
    m.read("kind", h.kind);
    const cv::FileNode pose = m.child("pose");
    if (!pose.empty()) h.pose = pose2(pose, m.name("pose"));
    m.read("sigma_x_m", h.sigma_x_m);
    m.read("sigma_y_m", h.sigma_y_m);
    m.read("sigma_theta_deg", h.sigma_theta_deg);
    s.hints.push_back(h);
  });
  forEachMap(top, "faults", [&](YamlMap& m) { readFault(m, s.faults.emplace_back()); });
  top.finish();
  try {
    validateScenario(s);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return s;
}

}  // namespace

Scenario loadScenario(const std::string& path) {
  try {
    return readScenarioFile(path);
  } catch (const std::length_error& e) {
    // OpenCV 4.6 hands out a garbage string for some malformed keys (tests/fuzz/scenario_yaml
    // found one in 61 s): report it against the file instead of as "basic_string::_M_create".
    throw std::runtime_error(path + ": malformed key or value (" + e.what() + ")");
  }
}

}  // namespace houghloc
