#include "tools/node/node_core.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "tools/lcm/message_conversion.h"

namespace houghloc {
namespace {

std::string seconds(std::int64_t us) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f", 1e-6 * static_cast<double>(us));
  return text;
}

void append(std::string& message, const std::string& part) {
  if (part.empty()) return;
  message += (message.empty() ? "" : "; ") + part;
}

// No clock gives a time outside [0, 2^53) us (285 years). Inside it, every difference of two
// times fits in int64 and every time converts to double exactly, so the node's time arithmetic
// needs no overflow check of its own.
constexpr std::int64_t kUtimeLimit = std::int64_t{1} << 53;
bool plausibleUtime(std::int64_t utime) { return utime >= 0 && utime < kUtimeLimit; }

}  // namespace

NodeCore::NodeCore(std::shared_ptr<const FieldModel> field, const PipelineConfig& config,
                   const std::map<std::string, CameraIntrinsics>& cameras,
                   const NodeTimingConfig& timing)
    : pipeline_(PipelineMode::kFull, std::move(field), config), cameras_(cameras), timing_(timing) {
  for (const auto& [id, intrinsics] : cameras_) pipeline_.setCamera(id, intrinsics);
}

void NodeCore::drop(DropReason reason, const std::string& message) {
  drops_.add(reason);
  problem_ = message;
  problem_utime_ = last_utime_;
  for (const auto& [id, t] : newest_image_utime_) problem_utime_ = std::max(problem_utime_, t);
}

bool NodeCore::refuseTime(std::int64_t utime, const char* kind, const std::string* camera_id) {
  if (plausibleUtime(utime)) return false;
  const std::string what = camera_id ? "camera '" + *camera_id + "': " + kind : kind;
  drop(DropReason::kMalformed, what + " with utime " + std::to_string(utime) + " out of range");
  return true;
}

void NodeCore::onOdometry(const odometry_t& msg) {
  if (refuseTime(msg.utime, "odometry")) return;
  const std::optional<Pose2> odometry = odometryFromMessage(msg);
  if (!odometry) return drop(DropReason::kMalformed, "odometry with NaN or infinity");
  odometry_.push(msg.utime, *odometry);
}

void NodeCore::onCameraPose(const camera_pose_t& msg) {
  if (refuseTime(msg.utime, "pose", &msg.camera_id)) return;
  const std::optional<Pose3> pose = cameraPoseFromMessage(msg);
  if (!pose)
    return drop(DropReason::kMalformed, "camera '" + msg.camera_id + "': pose with NaN or inf");
  camera_poses_[msg.camera_id].push(msg.utime, *pose);
}

void NodeCore::onHint(const localization_hint_t& msg) {
  if (refuseTime(msg.utime, "hint")) return;
  try {
    pipeline_.queueHint(hintFromMessage(msg));
  } catch (const MessageError& e) {
    drop(DropReason::kMalformed, e.what());
  }
}

std::optional<NodeOutput> NodeCore::onImage(const image_t& msg) {
  const auto camera = cameras_.find(msg.camera_id);
  if (camera == cameras_.end()) {
    drop(DropReason::kMalformed, "image of unknown camera '" + msg.camera_id + "'");
    return std::nullopt;
  }
  if (refuseTime(msg.utime, "image", &msg.camera_id)) return std::nullopt;
  const auto last = last_image_utime_.find(msg.camera_id);
  if (last != last_image_utime_.end() && msg.utime <= last->second) {
    if (last->second - msg.utime <= timing_.restart_gap_us) {
      drop(DropReason::kOldImage, "camera '" + msg.camera_id + "': image older than the last");
      return std::nullopt;
    }
    // The publisher's clock started again: the buffers restart with its next samples
    // (StampedBuffer) and the Localizer treats the step back as a frame without motion.
    ++restarts_;
    restart_text_ = "camera '" + msg.camera_id + "': image times went back " +
                    seconds(last->second - msg.utime) + " s (publisher restarted; " +
                    std::to_string(restarts_) + " restart(s))";
    last_image_utime_.clear();
    newest_image_utime_.clear();
  }
  std::int64_t& newest = newest_image_utime_[msg.camera_id];
  newest = std::max(newest, msg.utime);
  cv::Mat image;
  try {
    image = imageFromMessage(msg);
  } catch (const MessageError& e) {
    drop(DropReason::kMalformed, "camera '" + msg.camera_id + "': " + e.what());
    return std::nullopt;
  }
  const CameraIntrinsics& intrinsics = camera->second;
  if (image.cols != intrinsics.image_width || image.rows != intrinsics.image_height) {
    drop(DropReason::kBadSize, "camera '" + msg.camera_id + "': image " +
                                   std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                                   ", camera.yaml " + std::to_string(intrinsics.image_width) + "x" +
                                   std::to_string(intrinsics.image_height));
    return std::nullopt;
  }
  const auto poses = camera_poses_.find(msg.camera_id);
  std::optional<Pose3> robot_T_camera;
  if (poses != camera_poses_.end())
    robot_T_camera = poses->second.at(msg.utime, timing_.max_camera_pose_gap_us);
  const auto fixed = static_camera_poses_.find(msg.camera_id);
  if (!robot_T_camera && fixed != static_camera_poses_.end()) robot_T_camera = fixed->second;
  if (!robot_T_camera) {
    drop(DropReason::kNoCameraPose, "camera '" + msg.camera_id + "': no camera pose within 50 ms");
    return std::nullopt;
  }
  last_image_utime_[msg.camera_id] = msg.utime;
  const PipelineFrame frame{msg.utime, msg.camera_id, *robot_T_camera,
                            odometry_.at(msg.utime, timing_.max_odometry_gap_us)};
  const auto start = std::chrono::steady_clock::now();
  const SeenFrame seen = pipeline_.see(frame, image);
  const PipelineResult result = pipeline_.locate(seen);
  last_cycle_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ++frames_processed_;
  last_utime_ = msg.utime;
  last_estimate_ = result.estimate;

  NodeOutput out;
  out.hypotheses = hypothesesToMessage(msg.utime, result.estimate);
  out.line_points.utime = msg.utime;
  out.line_points.camera_id = msg.camera_id;
  for (const GroundPoint& p : seen.vision.ground.points) {
    out.line_points.x.push_back(static_cast<float>(p.p_robot.x()));
    out.line_points.y.push_back(static_cast<float>(p.p_robot.y()));
  }
  out.line_points.num_points = static_cast<std::int32_t>(out.line_points.x.size());
  return out;
}

void NodeCore::setStaticCameraPose(const std::string& camera_id, const Pose3& robot_T_camera) {
  static_camera_poses_[camera_id] = robot_T_camera;
}

void NodeCore::setStaticCameraPoses(const std::map<std::string, Pose3>& poses,
                                    const std::string& config_file) {
  for (const auto& [id, pose] : poses) {
    if (!cameras_.count(id))
      throw std::runtime_error(config_file + ": node.static_camera_pose." + id +
                               ": no --camera-yaml for camera '" + id + "'");
    setStaticCameraPose(id, pose);
  }
}

void NodeCore::restorePose(const GaussianPose& field_T_robot) {
  LocalizationHint hint;
  hint.kind = HintKind::kResetTo;
  hint.t_us = std::numeric_limits<std::int64_t>::min();  // before any image of any clock
  hint.poses = {field_T_robot};
  pipeline_.queueHint(hint);
}

void NodeCore::setCondition(const std::string& key, const std::string& text) {
  conditions_[key] = text;
}

std::string NodeCore::streamGaps() const {
  if (newest_image_utime_.empty()) return "";
  std::string newest_camera;
  std::int64_t newest = std::numeric_limits<std::int64_t>::min();
  for (const auto& [id, t] : newest_image_utime_)
    if (t > newest) newest = t, newest_camera = id;
  const std::int64_t gap = timing_.max_stream_gap_us;
  std::string text;
  const std::optional<std::int64_t> odometry = odometry_.newest();
  if (odometry && std::abs(newest - *odometry) > gap)
    append(text, "odometry " + seconds(std::abs(newest - *odometry)) + " s apart from the images");
  for (const auto& [id, t] : newest_image_utime_) {
    if (newest - t > gap)
      append(text, "camera '" + id + "': images " + seconds(newest - t) + " s behind camera '" +
                       newest_camera + "'");
    const auto poses = camera_poses_.find(id);
    const std::optional<std::int64_t> pose_t =
        poses == camera_poses_.end() ? std::nullopt : poses->second.newest();
    if (pose_t && std::abs(t - *pose_t) > gap)
      append(text, "camera '" + id + "': camera poses " + seconds(std::abs(t - *pose_t)) +
                       " s apart from its images");
  }
  return text;
}

localizer_status_t NodeCore::status() const {
  localizer_status_t msg{};
  msg.utime = last_utime_;
  msg.state = statusToMessage(last_estimate_.status);
  msg.cycle_time_ms = last_cycle_ms_;
  msg.points_in = last_estimate_.points_in;
  msg.points_used = last_estimate_.points_used;
  msg.frames_processed = frames_processed_;
  drops_.fill(msg);
  for (const auto& [key, text] : conditions_) append(msg.message, text);
  append(msg.message, streamGaps());
  append(msg.message, restart_text_);
  // A refusal is "what is wrong now" until 1 s of images went through after it.
  if (!problem_.empty() && last_utime_ - problem_utime_ <= timing_.max_stream_gap_us)
    append(msg.message, "last drop: " + problem_);
  return msg;
}

}  // namespace houghloc
