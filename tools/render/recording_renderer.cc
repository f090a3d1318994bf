#include "tools/render/recording_renderer.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <stdexcept>

#include "tools/recording/csv.h"
#include "tools/recording/recording.h"
#include "tools/render/camera_rig.h"
#include "tools/render/faults.h"
#include "tools/render/image_renderer.h"
#include "tools/render/moving_objects.h"
#include "tools/render/odometry_model.h"
#include "tools/render/sensor_effects.h"
#include "tools/render/trajectory.h"
#include "tools/render/visibility.h"
#include "vision/camera_presets.h"

namespace houghloc {
namespace {

constexpr double kMaxBlur_px = 60.0;  ///< larger image motion is a jump (kidnap), not blur

std::int64_t toMicros(double t_s) { return std::llround(t_s * 1e6); }

FrameView makeView(const Pose2& field_T_robot, const Pose3& robot_T_camera) {
  FrameView view;
  const Eigen::Matrix3d rz =
      Eigen::AngleAxisd(field_T_robot.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  view.field_R_camera = rz * robot_T_camera.rotation();
  view.origin =
      rz * robot_T_camera.translation() + Eigen::Vector3d(field_T_robot.x, field_T_robot.y, 0.0);
  return view;
}

/// Image motion (px) of the image centre's scene point from t - exposure to t.
Eigen::Vector2d centreMotion(const RenderJob& job, const Pose3& mount, const Trajectory& trajectory,
                             const CameraModel& now, const Pose2& pose_now, double t) {
  const SensorConfig& sensor = job.scenario.sensor;
  const bool blur_fault = activeFault(job.scenario.faults, "motion_blur", t) != nullptr;
  if (!(sensor.motion_blur || blur_fault) || trajectory.independentFrames()) {
    return Eigen::Vector2d::Zero();
  }
  const double cx = 0.5 * (now.width() - 1), cy = 0.5 * (now.height() - 1);
  const Eigen::Vector3d ray = now.pixelRay(cx, cy);
  if (!std::isfinite(ray.x())) return Eigen::Vector2d::Zero();
  const Eigen::Vector3d cam = now.pose().translation();
  // The scene point: the ground hit, or 6 m away above the horizon.
  const double range = ray.z() < -1e-3 ? std::min(6.0, -cam.z() / ray.z()) : 6.0;
  const Eigen::Vector3d p_robot = cam + range * ray;
  const Eigen::Vector2d p_field_xy = pose_now.transform(p_robot.head<2>());
  const double t0 = t - 1e-3 * exposureTimeAt(sensor, job.scenario.faults, t);
  const RobotState before = trajectory.at(t0);
  CameraModel then(now.intrinsics(), renderedCameraPose(mount, before, t0, job.scenario));
  const Eigen::Vector2d p_before = before.field_T_robot.inverse().transform(p_field_xy);
  const auto pixel = then.project(Eigen::Vector3d(p_before.x(), p_before.y(), p_robot.z()));
  if (!pixel) return Eigen::Vector2d::Zero();
  const Eigen::Vector2d motion = Eigen::Vector2d(cx, cy) - *pixel;
  return motion.norm() > kMaxBlur_px ? Eigen::Vector2d::Zero() : motion;
}

std::vector<HintRecord> makeHints(const Scenario& s, const Trajectory& trajectory) {
  std::vector<HintRecord> hints;
  for (const HintConfig& h : s.hints) {
    HintRecord r;
    r.t_us = toMicros(h.t_s);
    r.kind = h.kind;
    r.pose = h.pose;
    if (!r.pose && (h.kind == "RESET_TO" || h.kind == "ADD")) {
      r.pose = trajectory.at(h.t_s).field_T_robot;
    }
    r.sigma_x = h.sigma_x_m;
    r.sigma_y = h.sigma_y_m;
    r.sigma_theta = h.sigma_theta_deg * M_PI / 180.0;
    hints.push_back(r);
  }
  return hints;
}

/// Per camera of the rig: what renders and records its frames.
struct CameraResources {
  RigCamera spec;
  RayTable rays;
  SensorModel sensor;
  CameraModel camera;
};

std::vector<CameraResources> makeCameraResources(const RenderJob& job) {
  std::vector<RigCamera> specs = job.rig;
  if (specs.empty()) specs.push_back({"", job.intrinsics, job.mount});
  std::vector<CameraResources> out;
  for (const RigCamera& spec : specs) {
    const SensorConfig& sensor = job.scenario.sensor;
    out.push_back({spec, makeRayTable(spec.intrinsics, sensor.supersampling),
                   SensorModel(sensor, spec.intrinsics.image_width, spec.intrinsics.image_height),
                   CameraModel(spec.intrinsics, spec.mount)});
  }
  return out;
}

/// The recorded camera pose (frames.csv cam_*): the rendered one, or during a camera_pose_delay
/// fault the pose the same camera had delay_ms earlier; then the scenario's calibration error
/// and a camera_pitch_error fault's.
Pose3 recordedPose(const Scenario& sc, const Trajectory& trajectory, const Pose3& mount,
                   const Pose3& rendered, double t, std::mt19937& noise) {
  Pose3 pose = rendered;
  if (const FaultConfig* delay = activeFault(sc.faults, "camera_pose_delay", t)) {
    const double then = std::max(0.0, t - 1e-3 * delay->delay_ms);
    pose = renderedCameraPose(mount, trajectory.at(then), then, sc);
  }
  pose.pitch += recordedPitchError(sc.faults, t);
  return recordedCameraPose(pose, sc.camera_pose_error, noise);
}

/// truth/faults.csv: one row per fault window, for measuring recovery from its end (none without
/// faults, also when an earlier render into the folder left one).
void writeFaults(const Scenario& sc, const std::filesystem::path& path) {
  if (sc.faults.empty()) {
    std::filesystem::remove(path);
    return;
  }
  CsvWriter out(path.string(), {"t_start_us", "t_end_us", "fault"});
  for (const FaultConfig& f : sc.faults) {
    out.writeRow({out.format(toMicros(f.start_s)), out.format(toMicros(f.end_s)), f.kind});
  }
  out.close();
}

/// writeRecording() leaves out empty files; a rendered folder always has both truth files.
void writeHeaderIfMissing(const std::filesystem::path& path, const char* header) {
  if (std::filesystem::exists(path)) return;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << header << "\n";
}

}  // namespace

void useNaoCameraRig(RenderJob* job) {
  job->rig.clear();
  for (const char* id : {"nao-top", "nao-bottom"}) {
    const CameraPreset preset = cameraPreset(id);
    job->rig.push_back({id, preset.intrinsics, preset.robot_T_camera});
  }
  job->intrinsics = job->rig.front().intrinsics;
  job->mount = job->rig.front().mount;
}

void renderRecording(const RenderJob& job, const RenderProgress& progress) {
  const Scenario& sc = job.scenario;
  validateScenario(sc);
  namespace fs = std::filesystem;
  const fs::path out(job.out_dir);
  fs::create_directories(out / "images");

  const Trajectory trajectory(sc, job.field);
  OdometryModel odometry(sc.odometry, sc.seed, sc.fps);
  std::vector<CameraResources> cameras = makeCameraResources(job);
  const RoomBox box = makeRoomBox(job.field, sc.scene);
  const GroundShader ground(job.field, sc.scene, box, sc.seed);
  const RoomShader room(box, sc.scene, sc.seed);
  SceneObjects statics = makeGoals(job.field, sc.scene);
  statics.append(makePeople(job.field, sc.scene, box, sc.seed));
  const MovingObjects movers(sc, job.field);
  const VisibilityCounter visibility(job.field);
  std::mt19937 pose_noise(sc.seed * 19u + 1u);
  std::mt19937 frame_drops(sc.seed * 23u + 5u);
  const double own_height = job.mount.z / 0.86;  // NAO: camera at 86% of the robot's height
  const double others_height =
      sc.scene.robot_height_m > 0.0 ? sc.scene.robot_height_m : defaultRobotHeight(job.field);

  Recording rec;
  for (const CameraResources& c : cameras) {
    if (c.spec.id.empty()) {
      rec.camera = c.spec.intrinsics;
    } else {
      rec.cameras[c.spec.id] = c.spec.intrinsics;
    }
  }
  rec.field = job.field;
  RenderBuffers buffers;
  const bool png = sc.sensor.image_format == "png";
  const std::vector<int> params =
      png ? std::vector<int>{cv::IMWRITE_PNG_COMPRESSION, 3}
          : std::vector<int>{cv::IMWRITE_JPEG_QUALITY, sc.sensor.jpeg_quality};
  double t_prev = 0.0;
  for (int i = 0; i < sc.frames; ++i) {
    const double t = i / sc.fps;
    const std::int64_t t_us = toMicros(t);
    const RobotState state = trajectory.at(t);
    CameraResources& rig = cameras[static_cast<size_t>(i) % cameras.size()];
    CameraModel& camera = rig.camera;
    const Pose3 cam_pose = renderedCameraPose(rig.spec.mount, state, t, sc);
    // Odometry, recorded camera pose and truth go on through frames a frame_drop fault leaves
    // out (their noise too), so the recorded frames are those of the run without the fault.
    if (i > 0) {
      odometry.update(recordedOdometryStep(sc.faults, trajectory.walkedMotion(t_prev, t), t));
    }
    t_prev = t;
    const Pose3 recorded_pose =
        recordedPose(sc, trajectory, rig.spec.mount, cam_pose, t, pose_noise);
    rec.ground_truth.push_back({t_us, state.field_T_robot});
    if (frameDropped(sc.faults, t, frame_drops)) {
      if (progress) progress(i + 1, sc.frames);
      continue;
    }
    camera.setPose(cam_pose);
    const FrameView view = makeView(state.field_T_robot, cam_pose);
    SceneObjects objects = statics;
    objects.append(movers.at(t, state.field_T_robot));
    objects.append(faultRobots(sc.faults, t, state.field_T_robot, state.pan_rad, others_height));
    if (sc.scene.own_feet && state.fall_phase < 0.0) {
      addOwnFeet(state.field_T_robot, own_height, M_PI * sc.trajectory.gait_frequency_hz * t,
                 state.walk_speed_mps > 0.01, objects);
    }
    ImageRenderer(rig.rays, ground, room, box).render(view, objects, buffers);
    const Eigen::Vector2d motion =
        centreMotion(job, rig.spec.mount, trajectory, camera, state.field_T_robot, t);
    const cv::Mat3b image =
        rig.sensor.apply(buffers.bgr, applyLightFaults(exposureAt(sc.sensor, t), sc.faults, t),
                         motion, static_cast<std::uint64_t>(sc.seed) * 1000003ull + i);
    char name[32];
    std::snprintf(name, sizeof(name), "images/%06d.%s", i, png ? "png" : "jpg");
    if (!cv::imwrite((out / name).string(), image, params)) {
      throw std::runtime_error((out / name).string() + ": cannot write image");
    }
    const auto visible =
        visibility.count(t_us, state.field_T_robot, camera, view, rig.rays, buffers);
    rec.visible.insert(rec.visible.end(), visible.begin(), visible.end());
    FrameRecord frame;
    frame.image = name;
    frame.t_us = t_us;
    // An odometry_dropout leaves the frame without odometry, as the node sees a silent source.
    if (activeFault(sc.faults, "odometry_dropout", t)) {
      frame.odometry = std::nullopt;
    } else {
      frame.odometry = odometry.pose();
    }
    frame.camera_id = rig.spec.id;
    frame.robot_T_camera = recorded_pose;
    rec.frames.push_back(frame);
    if (progress) progress(i + 1, sc.frames);
  }
  for (const TrajectoryEvent& e : trajectory.events()) {
    if (e.t_s < sc.frames / sc.fps) rec.events.push_back({toMicros(e.t_s), e.event});
  }
  rec.hints = makeHints(sc, trajectory);
  writeRecording(rec, job.out_dir);
  writeHeaderIfMissing(out / "truth" / "visible.csv",
                       "t_us,feature,visible_length_m,direction_deg");
  writeHeaderIfMissing(out / "truth" / "events.csv", "t_us,event");
  writeFaults(sc, out / "truth" / "faults.csv");
}

}  // namespace houghloc
