#include "tools/render/scenario.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "tools/render/faults.h"

namespace houghloc {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

namespace {

bool oneOf(const std::string& value, std::initializer_list<const char*> names) {
  return std::any_of(names.begin(), names.end(), [&](const char* n) { return value == n; });
}

}  // namespace

void validateScenario(const Scenario& s) {
  require(s.fps > 0.0 && s.fps <= 1000.0, "fps: must be in (0, 1000]");
  require(s.frames >= 0, "frames: must not be negative");
  const TrajectoryConfig& t = s.trajectory;
  require(oneOf(t.name, {"walk", "spin", "kidnap", "fall", "random-poses", "waypoints"}),
          "trajectory.name: unknown trajectory '" + t.name +
              "' (known: walk, spin, kidnap, fall, random-poses, waypoints)");
  require(t.name != "waypoints" || !t.waypoints.empty(),
          "trajectory.waypoints: needs at least one waypoint");
  for (size_t i = 0; i < t.waypoints.size(); ++i) {
    require(t.waypoints[i].speed_mps > 0.0,
            "trajectory.waypoints[" + std::to_string(i) + "]: speed must be positive");
  }
  require(t.walk_speed_mps > 0.0, "trajectory.walk_speed_mps: must be positive");
  require(t.turn_speed_dps > 0.0, "trajectory.turn_speed_dps: must be positive");
  require(oneOf(s.head.mode, {"auto", "fixed", "sweep", "schedule"}),
          "head.mode: unknown mode '" + s.head.mode + "' (known: auto, fixed, sweep, schedule)");
  require(s.head.mode != "schedule" || !s.head.schedule.empty(),
          "head.schedule: needs at least one key");
  require(s.head.sweep_period_s > 0.0, "head.sweep_period_s: must be positive");
  for (size_t i = 0; i < s.falls.size(); ++i) {
    require(s.falls[i].duration_s > 0.5,
            "falls[" + std::to_string(i) + "].duration_s: must exceed 0.5 s");
  }
  require(s.odometry.slip_factor >= 0.0 && s.odometry.slip_factor <= 2.0,
          "odometry.slip_factor: must be in [0, 2]");
  for (size_t i = 0; i < s.robots.size(); ++i) {
    require(oneOf(s.robots[i].team, {"red", "blue", "black", "yellow", "green", "white"}),
            "robots[" + std::to_string(i) + "].team: unknown colour '" + s.robots[i].team + "'");
  }
  require(s.ball.diameter_m >= 0.0, "ball.diameter_m: must not be negative");
  const SceneConfig& c = s.scene;
  require(c.line_wear >= 0.0 && c.line_wear <= 1.0, "scene.line_wear: must be in [0, 1]");
  require(c.stripe_width_m > 0.0, "scene.stripe_width_m: must be positive");
  require(c.people >= 0 && c.people <= 100, "scene.people: must be in [0, 100]");
  require(c.random_robots >= 0 && c.random_robots <= 20, "scene.random_robots: must be in [0, 20]");
  require(c.room_margin_m >= 0.5, "scene.room_margin_m: must be at least 0.5");
  for (const auto& [name, bgr] : {std::pair{"turf_bgr", c.turf_bgr}, {"paint_bgr", c.paint_bgr}}) {
    for (double v : bgr) {
      require(v >= 0.0 && v <= 255.0,
              std::string("scene.") + name + ": components must be in [0, 255]");
    }
  }
  require(c.hall_brightness >= 0.0 && c.hall_brightness <= 4.0,
          "scene.hall_brightness: must be in [0, 4]");
  const SensorConfig& n = s.sensor;
  require(n.exposure > 0.0, "sensor.exposure: must be positive");
  require(n.color_temperature_k >= 1500.0 && n.color_temperature_k <= 15000.0,
          "sensor.color_temperature_k: must be in [1500, 15000]");
  require(n.tint >= -1.0 && n.tint <= 1.0, "sensor.tint: must be in [-1, 1]");
  for (size_t i = 0; i < n.light_changes.size(); ++i) {
    const LightChange& l = n.light_changes[i];
    const std::string at = "sensor.light_changes[" + std::to_string(i) + "]";
    require(l.exposure > 0.0, at + ".exposure: must be positive");
    require(l.color_temperature_k >= 1500.0 && l.color_temperature_k <= 15000.0,
            at + ".color_temperature_k: must be in [1500, 15000]");
  }
  require(n.supersampling >= 1 && n.supersampling <= 4, "sensor.supersampling: must be 1 to 4");
  require(oneOf(n.image_format, {"jpg", "png"}), "sensor.image_format: must be jpg or png");
  require(n.jpeg_quality >= 10 && n.jpeg_quality <= 100, "sensor.jpeg_quality: must be 10 to 100");
  require(n.vignetting >= 0.0 && n.vignetting < 1.0, "sensor.vignetting: must be in [0, 1)");
  require(n.noise_sigma >= 0.0 && n.shot_noise >= 0.0, "sensor.noise_sigma: must not be negative");
  for (size_t i = 0; i < s.hints.size(); ++i) {
    require(oneOf(s.hints[i].kind, {"UNKNOWN", "RESET_TO", "ADD", "OWN_HALF", "MIRROR"}),
            "hints[" + std::to_string(i) + "].kind: unknown kind '" + s.hints[i].kind + "'");
  }
  for (size_t i = 0; i < s.faults.size(); ++i) validateFault(s.faults[i], i);
}

}  // namespace houghloc
