#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "field_models/pose2.h"
#include "field_models/pose3.h"

namespace houghloc {

// Everything a render run can be told (DESIGN §5.4). Every member has a default, so an empty
// scenario renders a plausible recording. The YAML keys equal the member names (docs/render.md).

/// One waypoint: the robot walks in a straight line to it at `speed_mps`, turning at most at
/// TrajectoryConfig::turn_speed_dps.
struct Waypoint {
  double x_m = 0.0, y_m = 0.0;
  double theta_deg = 0.0;  ///< field-frame heading on arrival
  double speed_mps = 0.25;
};

struct TrajectoryConfig {
  std::string name = "walk";  ///< walk | spin | kidnap | fall | random-poses | waypoints
  std::vector<Waypoint> waypoints;
  bool loop = true;                        ///< waypoints: start over at the end
  double walk_speed_mps = 0.25;            ///< built-in walking trajectories
  double turn_speed_dps = 40.0;            ///< maximum turning rate while walking
  double spin_rate_dps = 30.0;             ///< spin: turning rate on the spot
  double spin_x_m = -1.5, spin_y_m = 1.0;  ///< spin: where
  double gait_sway_deg = 1.0;              ///< camera roll/pitch wobble amplitude while walking
  double gait_frequency_hz = 1.8;          ///< step frequency of that wobble
  double random_margin_m = 0.3;            ///< random-poses: how far beyond the lines poses may lie
};

/// Head joint motion on top of the camera's mount (robot_T_camera of the preset).
struct HeadKey {
  double t_s = 0.0, pan_deg = 0.0, tilt_deg = 0.0;
};
struct HeadConfig {
  std::string mode = "auto";  ///< auto (sweep when walking, else fixed) | fixed | sweep | schedule
  double pan_deg = 0.0;       ///< fixed pan, and the centre of the sweep
  double tilt_deg = 0.0;      ///< added to the mount's pitch (positive looks down)
  double sweep_amplitude_deg = 40.0;
  double sweep_period_s = 8.0;
  std::vector<HeadKey> schedule;             ///< mode schedule: linear between keys
  double neck_height_below_camera_m = 0.06;  ///< pan/tilt pivot below the optical centre
};

struct KidnapConfig {
  double t_s = 0.0;
  std::optional<Pose2> to;  ///< where the robot reappears; none: elsewhere on its path
};
struct FallConfig {
  double t_s = 0.0;
  double duration_s = 3.0;  ///< FALL_START to FALL_END
};

/// Odometry errors (DESIGN §3: cumulative odometry pose); noise is proportional to motion.
struct OdometryConfig {
  double translation_noise = 0.05;            ///< sigma per metre walked (fraction)
  double rotation_noise = 0.05;               ///< sigma per radian turned (fraction)
  double rotation_per_metre_noise_deg = 2.0;  ///< heading sigma per metre walked
  double scale_bias = 0.05;                   ///< reported translation = true * (1 + scale_bias)
  double rotation_bias = -0.03;               ///< reported rotation = true * (1 + rotation_bias)
  double slip_rate_hz = 0.05;                 ///< how often the feet slip
  double slip_duration_s = 0.6;
  double slip_factor = 0.4;  ///< during a slip the robot really moves only this fraction
};

struct RobotConfig {
  double x_m = 0.0, y_m = 0.0, theta_deg = 0.0;
  std::string team = "blue";  ///< red | blue | black | yellow | green | white (jersey colour)
  double vx_mps = 0.0, vy_mps = 0.0;  ///< field-frame drift; bounces off the carpet edge
};

struct BallConfig {
  bool enabled = true;
  std::optional<double> x_m, y_m;  ///< none: random on the field
  double vx_mps = 0.0, vy_mps = 0.0;
  double diameter_m = 0.0;  ///< 0: from the field (SPL 0.1, others 0.15 / 0.22)
};

/// What the world looks like. Every effect can be switched off.
struct SceneConfig {
  bool turf_texture = true;
  bool mowing_stripes = true;
  double stripe_width_m = 0.5;
  double stripe_contrast = 0.05;  ///< relative brightness difference of the stripes
  bool lighting_gradient = true;
  double lighting_strength = 0.12;       ///< relative brightness variation over the field
  double line_wear = 0.4;                ///< 0 = perfect paint; 1 = strongly worn and dirty lines
  double line_edge_roughness_m = 0.002;  ///< ragged turf edges of the lines
  bool goals = true;
  bool goal_nets = true;
  bool goal_frame = true;       ///< the white frame lying on the ground behind the goal line
  bool gym_floor = true;        ///< wooden floor beyond the carpet (else grey concrete)
  bool court_lines = true;      ///< other sports' lines on that floor
  bool walls = true;            ///< doors, windows, white boards, banners
  int people = 8;               ///< spectators standing around the carpet
  bool own_feet = true;         ///< the robot's own feet (visible from nao-bottom)
  bool shadows = true;          ///< soft contact shadows of robots and ball
  double room_margin_m = 3.0;   ///< floor between the carpet edge and the walls
  double robot_height_m = 0.0;  ///< 0: from the field (SPL 0.58, kid 0.8, adult 1.4)
  int random_robots = 0;        ///< extra robots walking around, placed by the seed
  /// Carpet colour (BGR, 0..255 before lighting): the default is a saturated green turf; real
  /// carpets are also yellowish, teal, desaturated, grey or black (docs/render.md).
  std::array<double, 3> turf_bgr = {52.0, 128.0, 62.0};
  /// Line paint or tape colour (BGR): dull or tinted tape lowers the lines' contrast.
  std::array<double, 3> paint_bgr = {222.0, 228.0, 228.0};
  double hall_brightness = 1.0;  ///< gain on walls and ceiling (dark curtains, bright windows)
};

struct LightChange {
  double t_s = 0.0;
  double exposure = 1.0;  ///< brightness gain from then on
  double color_temperature_k = 5500.0;
  double ramp_s = 0.5;  ///< auto exposure / white balance settling time
};

/// The camera as a sensor: exposure, optics and noise.
struct SensorConfig {
  double exposure = 1.0;                ///< brightness gain
  double color_temperature_k = 5500.0;  ///< light colour the white balance does not cancel
  /// Green (+) or magenta (-) cast the white balance does not cancel, -1..1 (green gain
  /// exp(0.25 tint)): fluorescent and LED hall lights.
  double tint = 0.0;
  std::vector<LightChange> light_changes;
  double vignetting = 0.25;     ///< brightness loss in the image corners (fraction)
  double optics_blur_px = 0.6;  ///< Gaussian sigma of the lens blur
  bool motion_blur = true;
  double exposure_time_ms = 4.0;     ///< motion blur length
  double noise_sigma = 3.0;          ///< Gaussian sensor noise, 8-bit units
  double shot_noise = 2.0;           ///< extra sigma at full brightness (sqrt law)
  bool yuv422 = true;                ///< halve the chroma resolution like the NAO's cameras
  int supersampling = 1;             ///< rays per pixel along each axis
  std::string image_format = "jpg";  ///< jpg | png
  int jpeg_quality = 90;
};

/// The recorded camera pose differs from the rendered one (calibration error, DESIGN §5.4).
struct CameraPoseError {
  Pose3 bias;              ///< added to the rendered x, y, z (m), roll, pitch, yaw (rad)
  double noise_deg = 0.0;  ///< per-frame Gaussian noise on roll, pitch and yaw
};

/// A fault injected from start_s to end_s (docs/render.md "Faults"), for measuring how the
/// localizer copes and how soon it recovers after end_s (truth/faults.csv). Only the parameters
/// of the fault's kind apply; the scenario YAML rejects the others.
struct FaultConfig {
  /// odometry_dropout: frames.csv repeats the last odometry received before start_s, then
  ///   jumps by everything walked meanwhile (cumulative odometry loses nothing).
  /// robots_in_view: robots standing in front of the camera, walking along with the robot.
  /// motion_blur: exposure_time_ms instead of the sensor's.
  /// light_change: the light's brightness and colour change (ramped in and out).
  /// camera_pose_delay: frames.csv cam_* is the camera pose of delay_ms earlier.
  /// odometry_scale: odometry reports `scale` times the walked motion (steps, turns).
  /// camera_pitch_error: frames.csv cam_pitch is off by pitch_deg (a miscalibrated joint).
  /// frame_drop: a random drop_fraction of the frames is not recorded (no image, no row).
  std::string kind;
  double start_s = 0.0, end_s = 1.0;
  int robots = 3;            ///< robots_in_view: how many
  double distance_m = 1.0;   ///< robots_in_view: from the robot's centre
  double spread_deg = 40.0;  ///< robots_in_view: bearings spread evenly over this, about the pan
  std::string team = "red";  ///< robots_in_view: jersey colour
  double exposure_time_ms = 40.0;       ///< motion_blur
  double exposure = 0.35;               ///< light_change: brightness gain factor
  double color_temperature_k = 3000.0;  ///< light_change: light colour meanwhile
  double ramp_s = 0.2;                  ///< light_change: from start_s in, and out ending at end_s
  double delay_ms = 100.0;              ///< camera_pose_delay
  double scale = 1.3;                   ///< odometry_scale: factor on every odometry step
  double pitch_deg = 2.0;               ///< camera_pitch_error: added to the recorded pitch
  double drop_fraction = 0.5;           ///< frame_drop: share of the frames not recorded
};

struct HintConfig {
  double t_s = 0.0;
  std::string kind = "RESET_TO";  ///< UNKNOWN | RESET_TO | ADD | OWN_HALF | MIRROR
  std::optional<Pose2> pose;      ///< none with RESET_TO / ADD: the true pose at t_s
  double sigma_x_m = 0.1, sigma_y_m = 0.1, sigma_theta_deg = 5.0;
};

struct Scenario {
  double fps = 30.0;
  int frames = 300;
  std::uint32_t seed = 1;
  std::string field;                  ///< standard name or map file; the command line overrides it
  std::string camera;                 ///< preset name or camera.yaml; the command line overrides it
  std::optional<Pose3> camera_mount;  ///< robot_T_camera instead of the preset's
  TrajectoryConfig trajectory;
  HeadConfig head;
  std::vector<KidnapConfig> kidnaps;
  std::vector<FallConfig> falls;
  OdometryConfig odometry;
  std::vector<RobotConfig> robots;
  BallConfig ball;
  SceneConfig scene;
  SensorConfig sensor;
  CameraPoseError camera_pose_error;
  std::vector<HintConfig> hints;
  std::vector<FaultConfig> faults;  ///< none by default
};

/// Reads a scenario YAML (cv::FileStorage). Throws std::runtime_error naming the file and the
/// key at fault (unknown keys, wrong types, out-of-range values).
Scenario loadScenario(const std::string& path);

/// Checks ranges (fps > 0, frames >= 0, known names ...); throws std::invalid_argument naming
/// the member at fault.
void validateScenario(const Scenario& scenario);

/// The scenario checks' way to fail: throws std::invalid_argument(what) unless ok.
void require(bool ok, const std::string& what);

}  // namespace houghloc
