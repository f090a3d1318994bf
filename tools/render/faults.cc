// Faults injected into a rendered recording for a time window (docs/render.md "Faults"): what
// the localizer has to survive during a match, each with a start and an end so that recovery
// can be measured from truth/faults.csv.
#include "tools/render/faults.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "field_models/angles.h"
#include "tools/render/yaml_map.h"

namespace houghloc {
namespace {

/// 0 outside [start, end], 1 inside, linear ramps of ramp_s at both ends inside the window.
double rampedShare(const FaultConfig& f, double t) {
  if (t < f.start_s || t >= f.end_s) return 0.0;
  if (f.ramp_s <= 0.0) return 1.0;
  return std::clamp(std::min(t - f.start_s, f.end_s - t) / f.ramp_s, 0.0, 1.0);
}

}  // namespace

const std::vector<std::string>& faultKinds() {
  static const std::vector<std::string> kinds = {
      "odometry_dropout",  "robots_in_view", "motion_blur",        "light_change",
      "camera_pose_delay", "odometry_scale", "camera_pitch_error", "frame_drop"};
  return kinds;
}

void readFault(YamlMap& m, FaultConfig& f) {
  m.read("kind", f.kind);
  m.read("start_s", f.start_s);
  m.read("end_s", f.end_s);
  if (f.kind == "robots_in_view") {
    m.read("robots", f.robots);
    m.read("distance_m", f.distance_m);
    m.read("spread_deg", f.spread_deg);
    m.read("team", f.team);
  } else if (f.kind == "motion_blur") {
    m.read("exposure_time_ms", f.exposure_time_ms);
  } else if (f.kind == "light_change") {
    m.read("exposure", f.exposure);
    m.read("color_temperature_k", f.color_temperature_k);
    m.read("ramp_s", f.ramp_s);
  } else if (f.kind == "camera_pose_delay") {
    m.read("delay_ms", f.delay_ms);
  } else if (f.kind == "odometry_scale") {
    m.read("scale", f.scale);
  } else if (f.kind == "camera_pitch_error") {
    m.read("pitch_deg", f.pitch_deg);
  } else if (f.kind == "frame_drop") {
    m.read("drop_fraction", f.drop_fraction);
  }
}

void validateFault(const FaultConfig& f, size_t index) {
  const std::string at = "faults[" + std::to_string(index) + "]";
  const auto& kinds = faultKinds();
  std::string known;
  for (const std::string& kind : kinds) known += (known.empty() ? "" : ", ") + kind;
  require(std::find(kinds.begin(), kinds.end(), f.kind) != kinds.end(),
          at + ".kind: unknown fault '" + f.kind + "' (known: " + known + ")");
  require(f.start_s >= 0.0, at + ".start_s: must not be negative");
  require(f.end_s > f.start_s, at + ".end_s: must be after start_s");
  require(f.robots >= 1 && f.robots <= 10, at + ".robots: must be 1 to 10");
  require(f.distance_m >= 0.3 && f.distance_m <= 10.0, at + ".distance_m: must be in [0.3, 10]");
  require(f.spread_deg >= 0.0 && f.spread_deg <= 180.0, at + ".spread_deg: must be in [0, 180]");
  const std::vector<std::string> teams = {"red", "blue", "black", "yellow", "green", "white"};
  require(std::find(teams.begin(), teams.end(), f.team) != teams.end(),
          at + ".team: unknown colour '" + f.team + "'");
  require(f.exposure_time_ms >= 0.0 && f.exposure_time_ms <= 200.0,
          at + ".exposure_time_ms: must be in [0, 200]");
  require(f.exposure > 0.0, at + ".exposure: must be positive");
  require(f.color_temperature_k >= 1500.0 && f.color_temperature_k <= 15000.0,
          at + ".color_temperature_k: must be in [1500, 15000]");
  // The ramps only apply to a light change (the default would not fit a short other fault).
  require(f.kind != "light_change" || (f.ramp_s >= 0.0 && 2.0 * f.ramp_s <= f.end_s - f.start_s),
          at + ".ramp_s: must be in [0, (end_s - start_s) / 2]");
  require(f.delay_ms >= 0.0 && f.delay_ms <= 2000.0, at + ".delay_ms: must be in [0, 2000]");
  require(f.scale >= 0.0 && f.scale <= 10.0, at + ".scale: must be in [0, 10]");
  require(std::abs(f.pitch_deg) <= 45.0, at + ".pitch_deg: must be in [-45, 45]");
  require(f.drop_fraction >= 0.0 && f.drop_fraction <= 1.0,
          at + ".drop_fraction: must be in [0, 1]");
}

const FaultConfig* activeFault(const std::vector<FaultConfig>& faults, const std::string& kind,
                               double t) {
  for (const FaultConfig& f : faults) {
    if (f.kind == kind && t >= f.start_s && t < f.end_s) return &f;
  }
  return nullptr;
}

Pose2 recordedOdometryStep(const std::vector<FaultConfig>& faults, const Pose2& walked, double t) {
  const FaultConfig* f = activeFault(faults, "odometry_scale", t);
  if (!f) return walked;
  return Pose2(f->scale * walked.x, f->scale * walked.y, f->scale * walked.theta);
}

double recordedPitchError(const std::vector<FaultConfig>& faults, double t) {
  const FaultConfig* f = activeFault(faults, "camera_pitch_error", t);
  return f ? f->pitch_deg * kDeg : 0.0;
}

bool frameDropped(const std::vector<FaultConfig>& faults, double t, std::mt19937& rng) {
  const FaultConfig* f = activeFault(faults, "frame_drop", t);
  return f && std::uniform_real_distribution<double>(0.0, 1.0)(rng) < f->drop_fraction;
}

double exposureTimeAt(const SensorConfig& sensor, const std::vector<FaultConfig>& faults,
                      double t) {
  const FaultConfig* blur = activeFault(faults, "motion_blur", t);
  return blur ? blur->exposure_time_ms : sensor.exposure_time_ms;
}

ExposureState applyLightFaults(ExposureState state, const std::vector<FaultConfig>& faults,
                               double t) {
  for (const FaultConfig& f : faults) {
    if (f.kind != "light_change") continue;
    const double share = rampedShare(f, t);
    if (share <= 0.0) continue;
    state.gain *= 1.0 + share * (f.exposure - 1.0);
    state.color_temperature_k += share * (f.color_temperature_k - state.color_temperature_k);
  }
  return state;
}

SceneObjects faultRobots(const std::vector<FaultConfig>& faults, double t,
                         const Pose2& field_T_robot, double pan_rad, double robot_height_m) {
  SceneObjects out;
  for (const FaultConfig& f : faults) {
    if (f.kind != "robots_in_view" || t < f.start_s || t >= f.end_s) continue;
    for (int i = 0; i < f.robots; ++i) {
      // Evenly over the spread, centred on the camera's viewing direction.
      const double offset = f.robots > 1 ? (i / (f.robots - 1.0) - 0.5) * f.spread_deg * kDeg : 0;
      const double bearing = pan_rad + offset;
      const Pose2 robot_T_other(f.distance_m * std::cos(bearing), f.distance_m * std::sin(bearing),
                                bearing + M_PI);  // facing the camera
      addRobot(field_T_robot * robot_T_other, robot_height_m, teamColour(f.team),
               2.0 * M_PI * 0.9 * t + i, true, out);
    }
  }
  return out;
}

}  // namespace houghloc
