// readRecording(): the folder layout of DESIGN §5.1 (docs/recording-format.md).
#include <filesystem>
#include <functional>
#include <set>

#include "field_models/field_yaml.h"
#include "tools/recording/csv.h"
#include "tools/recording/recording.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

const std::set<std::string> kHintKinds = {"UNKNOWN", "RESET_TO", "ADD", "OWN_HALF", "MIRROR"};
const std::set<std::string> kEvents = {"KIDNAP", "FALL_START", "FALL_END"};

/// Calls `parse` for each row after checking that t_us does not go backwards and, when
/// `strictly_increasing`, does not repeat either.
void forEachTimedRow(const CsvTable& table,
                     const std::function<void(const CsvRow&, std::int64_t)>& parse,
                     bool strictly_increasing = false) {
  const int t_column = table.column("t_us");
  bool first = true;
  std::int64_t previous = 0;
  for (const CsvRow& row : table.rows()) {
    const std::int64_t t_us = table.integer(row, t_column);
    if (!first && t_us < previous) {
      table.fail(row, "t_us goes backwards (" + std::to_string(t_us) + " after " +
                          std::to_string(previous) + ")");
    }
    if (!first && strictly_increasing && t_us == previous) {
      table.fail(row, "t_us repeats the previous row's (" + std::to_string(t_us) + ")");
    }
    first = false;
    previous = t_us;
    parse(row, t_us);
  }
}

CameraIntrinsics loadCamera(const fs::path& path) {
  try {
    return loadCameraYaml(path.string());
  } catch (const std::runtime_error& e) {
    throw RecordingError(e.what());  // already names the file and key
  }
}

/// odom_x, odom_y, odom_theta (columns c[0..2]): all numbers, or all empty for "no odometry".
std::optional<Pose2> readOdometry(const CsvTable& t, const CsvRow& row, const int c[3]) {
  const char* const names[] = {"odom_x", "odom_y", "odom_theta"};
  int empty = 0;
  for (int i = 0; i < 3; ++i) empty += CsvTable::text(row, c[i]).empty() ? 1 : 0;
  if (empty == 3) return std::nullopt;
  for (int i = 0; i < 3 && empty > 0; ++i) {
    if (CsvTable::text(row, c[i]).empty()) {
      t.fail(row, std::string("column '") + names[i] +
                      "' is empty but another odometry field is not (odom_x, odom_y and "
                      "odom_theta must be all given or all empty)");
    }
  }
  return Pose2(t.number(row, c[0]), t.number(row, c[1]), t.number(row, c[2]));
}

std::vector<FrameRecord> readFrames(const CsvTable& t) {
  std::vector<FrameRecord> frames;
  const int image = t.column("image");
  const char* const pose_names[] = {"odom_x", "odom_y",   "odom_theta", "cam_x",  "cam_y",
                                    "cam_z",  "cam_roll", "cam_pitch",  "cam_yaw"};
  int c[9];
  for (int i = 0; i < 9; ++i) c[i] = t.column(pose_names[i]);
  const auto camera = t.optionalColumn("camera");
  forEachTimedRow(t, [&](const CsvRow& row, std::int64_t t_us) {
    FrameRecord f;
    f.image = t.text(row, image);
    if (f.image.empty()) t.fail(row, "column 'image' is empty");
    f.t_us = t_us;
    f.odometry = readOdometry(t, row, c);
    f.robot_T_camera.x = t.number(row, c[3]);
    f.robot_T_camera.y = t.number(row, c[4]);
    f.robot_T_camera.z = t.number(row, c[5]);
    f.robot_T_camera.roll = t.number(row, c[6]);
    f.robot_T_camera.pitch = t.number(row, c[7]);
    f.robot_T_camera.yaw = t.number(row, c[8]);
    if (camera) f.camera_id = t.text(row, *camera);
    frames.push_back(std::move(f));
  });
  return frames;
}

std::vector<GroundTruthRecord> readGroundTruth(const CsvTable& t) {
  std::vector<GroundTruthRecord> truth;
  const int x = t.column("x"), y = t.column("y"), theta = t.column("theta");
  forEachTimedRow(
      t,
      [&](const CsvRow& row, std::int64_t t_us) {
        truth.push_back({t_us, Pose2(t.number(row, x), t.number(row, y), t.number(row, theta))});
      },
      /*strictly_increasing=*/true);  // one robot has one pose at a time
  return truth;
}

std::vector<HintRecord> readHints(const CsvTable& t) {
  std::vector<HintRecord> hints;
  const int kind = t.column("kind");
  const int x = t.column("x"), y = t.column("y"), theta = t.column("theta");
  const int sx = t.column("sigma_x"), sy = t.column("sigma_y"), st = t.column("sigma_theta");
  forEachTimedRow(t, [&](const CsvRow& row, std::int64_t t_us) {
    HintRecord h;
    h.t_us = t_us;
    h.kind = t.text(row, kind);
    if (kHintKinds.count(h.kind) == 0) {
      t.fail(row, "unknown hint kind '" + h.kind +
                      "' (expected UNKNOWN, RESET_TO, ADD, OWN_HALF or MIRROR)");
    }
    const auto px = t.optionalNumber(row, x), py = t.optionalNumber(row, y);
    const auto pt = t.optionalNumber(row, theta);
    if (px && py && pt) {
      h.pose = Pose2(*px, *py, *pt);
    } else if (px || py || pt) {
      t.fail(row, "x, y and theta must be all given or all empty");
    }
    h.sigma_x = t.optionalNumber(row, sx).value_or(0.0);
    h.sigma_y = t.optionalNumber(row, sy).value_or(0.0);
    h.sigma_theta = t.optionalNumber(row, st).value_or(0.0);
    hints.push_back(h);
  });
  return hints;
}

std::vector<VisibleRecord> readVisible(const CsvTable& t) {
  std::vector<VisibleRecord> visible;
  const int feature = t.column("feature"), length = t.column("visible_length_m");
  const int direction = t.column("direction_deg");
  forEachTimedRow(t, [&](const CsvRow& row, std::int64_t t_us) {
    if (t.text(row, feature).empty()) t.fail(row, "column 'feature' is empty");
    visible.push_back(
        {t_us, t.text(row, feature), t.number(row, length), t.number(row, direction)});
  });
  return visible;
}

std::vector<EventRecord> readEvents(const CsvTable& t) {
  std::vector<EventRecord> events;
  const int event = t.column("event");
  forEachTimedRow(t, [&](const CsvRow& row, std::int64_t t_us) {
    const std::string& name = t.text(row, event);
    if (kEvents.count(name) == 0) {
      t.fail(row, "unknown event '" + name + "' (expected KIDNAP, FALL_START or FALL_END)");
    }
    events.push_back({t_us, name});
  });
  return events;
}

/// camera.yaml, every cameras/<id>.yaml, and a check that each frame's camera exists.
void readCameras(const fs::path& folder, const CsvTable& frames_table, Recording* recording) {
  if (fs::exists(folder / "camera.yaml")) recording->camera = loadCamera(folder / "camera.yaml");
  if (fs::is_directory(folder / "cameras")) {
    for (const auto& entry : fs::directory_iterator(folder / "cameras")) {
      if (entry.path().extension() != ".yaml") continue;
      recording->cameras[entry.path().stem().string()] = loadCamera(entry.path());
    }
  }
  for (std::size_t i = 0; i < recording->frames.size(); ++i) {
    const std::string& id = recording->frames[i].camera_id;
    if (id.empty() && !recording->camera) {
      frames_table.fail(frames_table.rows()[i],
                        "missing camera: " + (folder / "camera.yaml").string() + " not found");
    }
    if (!id.empty() && recording->cameras.count(id) == 0) {
      frames_table.fail(frames_table.rows()[i],
                        "missing camera '" + id +
                            "': " + (folder / "cameras" / (id + ".yaml")).string() + " not found");
    }
  }
  if (recording->frames.empty() && !recording->camera && recording->cameras.empty()) {
    throw RecordingError((folder / "camera.yaml").string() + ": missing camera file");
  }
}

}  // namespace

Recording readRecording(const std::string& folder_name) {
  const fs::path folder(folder_name);
  if (!fs::is_directory(folder)) throw RecordingError(folder_name + ": not a folder");
  Recording recording;
  recording.folder = folder_name;
  const CsvTable frames = CsvTable::read((folder / "frames.csv").string());
  recording.frames = readFrames(frames);
  readCameras(folder, frames, &recording);
  auto optional = [&](const fs::path& relative, auto parse, auto* out) {
    if (fs::exists(folder / relative)) *out = parse(CsvTable::read((folder / relative).string()));
  };
  optional("groundtruth.csv", readGroundTruth, &recording.ground_truth);
  optional("hints.csv", readHints, &recording.hints);
  optional(fs::path("truth") / "visible.csv", readVisible, &recording.visible);
  optional(fs::path("truth") / "events.csv", readEvents, &recording.events);
  if (fs::exists(folder / "field.yaml")) {
    try {
      recording.field = readFieldYaml((folder / "field.yaml").string());
    } catch (const std::runtime_error& e) {
      throw RecordingError(e.what());  // FormatError names the file and entry
    }
  }
  return recording;
}

}  // namespace houghloc
