// writeRecording(): the CSV and YAML files of DESIGN §5.1, readable back exactly.
#include <filesystem>
#include <system_error>

#include "field_models/field_yaml.h"
#include "tools/recording/csv.h"
#include "tools/recording/recording.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

void createFolder(const fs::path& path) {
  std::error_code error;
  fs::create_directories(path, error);
  if (error) throw RecordingError(path.string() + ": cannot create folder: " + error.message());
}

void writeCamera(const fs::path& path, const CameraIntrinsics& intrinsics) {
  try {
    saveCameraYaml(path.string(), intrinsics);
  } catch (const std::runtime_error& e) {
    throw RecordingError(e.what());
  }
}

void writeFrames(const fs::path& path, const std::vector<FrameRecord>& frames) {
  bool any_camera_id = false;
  for (const FrameRecord& f : frames) any_camera_id |= !f.camera_id.empty();
  std::vector<std::string> header = {"image",      "t_us",      "odom_x", "odom_y",
                                     "odom_theta", "cam_x",     "cam_y",  "cam_z",
                                     "cam_roll",   "cam_pitch", "cam_yaw"};
  if (any_camera_id) header.push_back("camera");
  CsvWriter out(path.string(), header);
  for (const FrameRecord& f : frames) {
    const Pose3& c = f.robot_T_camera;
    // No odometry for the frame: all three fields empty (docs/recording-format.md).
    const auto odometry = [&](double Pose2::*member) {
      return f.odometry ? out.format((*f.odometry).*member) : std::string();
    };
    std::vector<std::string> row = {f.image,
                                    out.format(f.t_us),
                                    odometry(&Pose2::x),
                                    odometry(&Pose2::y),
                                    odometry(&Pose2::theta),
                                    out.format(c.x),
                                    out.format(c.y),
                                    out.format(c.z),
                                    out.format(c.roll),
                                    out.format(c.pitch),
                                    out.format(c.yaw)};
    if (any_camera_id) row.push_back(f.camera_id);
    out.writeRow(row);
  }
  out.close();
}

void writeGroundTruth(const fs::path& path, const std::vector<GroundTruthRecord>& truth) {
  CsvWriter out(path.string(), {"t_us", "x", "y", "theta"});
  for (const GroundTruthRecord& g : truth) {
    const Pose2& p = g.field_T_robot;
    out.writeRow({out.format(g.t_us), out.format(p.x), out.format(p.y), out.format(p.theta)});
  }
  out.close();
}

void writeHints(const fs::path& path, const std::vector<HintRecord>& hints) {
  CsvWriter out(path.string(),
                {"t_us", "kind", "x", "y", "theta", "sigma_x", "sigma_y", "sigma_theta"});
  for (const HintRecord& h : hints) {
    const auto pose = [&](double Pose2::*member) {
      return h.pose ? out.format((*h.pose).*member) : std::string();
    };
    out.writeRow({out.format(h.t_us), h.kind, pose(&Pose2::x), pose(&Pose2::y), pose(&Pose2::theta),
                  out.format(h.sigma_x), out.format(h.sigma_y), out.format(h.sigma_theta)});
  }
  out.close();
}

void writeVisible(const fs::path& path, const std::vector<VisibleRecord>& visible) {
  CsvWriter out(path.string(), {"t_us", "feature", "visible_length_m", "direction_deg"});
  for (const VisibleRecord& v : visible) {
    out.writeRow({out.format(v.t_us), v.feature, out.format(v.visible_length_m),
                  out.format(v.direction_deg)});
  }
  out.close();
}

void writeEvents(const fs::path& path, const std::vector<EventRecord>& events) {
  CsvWriter out(path.string(), {"t_us", "event"});
  for (const EventRecord& e : events) out.writeRow({out.format(e.t_us), e.event});
  out.close();
}

}  // namespace

void writeRecording(const Recording& recording, const std::string& folder_name) {
  const fs::path folder(folder_name);
  createFolder(folder);
  writeFrames(folder / "frames.csv", recording.frames);
  if (recording.camera) writeCamera(folder / "camera.yaml", *recording.camera);
  if (!recording.cameras.empty()) createFolder(folder / "cameras");
  for (const auto& [id, intrinsics] : recording.cameras) {
    writeCamera(folder / "cameras" / (id + ".yaml"), intrinsics);
  }
  if (!recording.ground_truth.empty()) {
    writeGroundTruth(folder / "groundtruth.csv", recording.ground_truth);
  }
  if (!recording.hints.empty()) writeHints(folder / "hints.csv", recording.hints);
  if (recording.field) {
    try {
      writeFieldYaml(*recording.field, (folder / "field.yaml").string());
    } catch (const std::runtime_error& e) {
      throw RecordingError(e.what());
    }
  }
  if (!recording.visible.empty() || !recording.events.empty()) createFolder(folder / "truth");
  if (!recording.visible.empty()) writeVisible(folder / "truth" / "visible.csv", recording.visible);
  if (!recording.events.empty()) writeEvents(folder / "truth" / "events.csv", recording.events);
}

}  // namespace houghloc
