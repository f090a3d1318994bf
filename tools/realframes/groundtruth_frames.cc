#include "tools/realframes/groundtruth_frames.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <opencv2/imgcodecs.hpp>

#include "field_models/standard_fields.h"
#include "localization/gaussian_pose.h"
#include "tools/realframes/coverage_overlay.h"
#include "tools/recording/csv.h"
#include "tools/recording/recording.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

bool hasGroundTruth(const fs::path& dir) { return fs::exists(dir / "groundtruth.csv"); }

/// frames.csv's fit_dpitch per t_us (rad); frames leaving it empty are not listed.
std::map<std::int64_t, double> fitDpitch(const fs::path& dir) {
  const CsvTable table = CsvTable::read((dir / "frames.csv").string());
  std::map<std::int64_t, double> out;
  const std::optional<int> column = table.optionalColumn("fit_dpitch");
  if (!column) return out;
  const int t_us = table.column("t_us");
  for (const CsvRow& row : table.rows()) {
    if (const auto d = table.optionalNumber(row, *column)) out[table.integer(row, t_us)] = *d;
  }
  return out;
}

bool within(const Pose2& a, const Pose2& b, const GlobalCheckConfig& check) {
  return (a.translation() - b.translation()).norm() <= check.position_m &&
         std::abs(angleDifference(a.theta, b.theta)) <= check.heading_rad;
}

}  // namespace

bool folderHasGroundTruth(const std::string& data_dir, const std::string& folder) {
  return hasGroundTruth(fs::path(data_dir) / folder);
}

bool folderHasFitDpitch(const std::string& data_dir, const std::string& folder) {
  return !fitDpitch(fs::path(data_dir) / folder).empty();
}

std::vector<GroundTruthFrameReport> groundTruthFrames(const std::string& data_dir,
                                                      const std::string& folder,
                                                      const std::vector<RealFrameOutcome>& outcomes,
                                                      const GroundTruthMetricsConfig& config) {
  const fs::path dir = fs::path(data_dir) / folder;
  std::vector<GroundTruthFrameReport> reports;
  if (!hasGroundTruth(dir)) return reports;
  const Recording recording = readRecording(dir.string());
  const FieldModel field = makeStandardField(realFolderStandard(folder));
  std::map<std::int64_t, const FrameRecord*> frames;
  for (const FrameRecord& f : recording.frames) frames[f.t_us] = &f;
  for (const RealFrameOutcome& o : outcomes) {
    if (o.label.lines_visible != "yes") continue;
    const auto frame = frames.find(o.label.t_us);
    const std::optional<Pose2> truth = groundTruthAt(recording.ground_truth, o.label.t_us);
    if (frame == frames.end() || !truth) continue;
    const CameraModel camera(recording.intrinsicsFor(*frame->second),
                             frame->second->robot_T_camera);
    GroundTruthFrameReport r;
    r.folder = folder;
    r.image = frame->second->image;
    r.t_us = o.label.t_us;
    r.field_T_robot = *truth;
    r.houghloc = groundTruthMetrics(field, *truth, camera, o.points_robot, config);
    r.baseline = groundTruthMetrics(field, *truth, camera, o.baseline_robot, config);
    reports.push_back(std::move(r));
  }
  return reports;
}

std::vector<GlobalCheckFrame> globalCheckAtGroundTruth(const std::string& data_dir,
                                                       const std::string& folder,
                                                       const PipelineConfig& config,
                                                       const GlobalCheckConfig& check) {
  return globalCheckAtGroundTruth(data_dir, std::vector<std::string>{folder}, config, check);
}

std::vector<GlobalCheckFrame> globalCheckAtGroundTruth(const std::string& data_dir,
                                                       const std::vector<std::string>& folders,
                                                       const PipelineConfig& config,
                                                       const GlobalCheckConfig& check) {
  std::vector<GlobalCheckFrame> out;
  if (folders.empty()) return out;
  // One robot's camera folders: each its recording; with more than one, a frame's camera id is
  // its folder's name (each folder's own camera.yaml).
  struct CameraFolder {
    std::string name;
    fs::path dir;
    Recording recording;
    std::map<std::int64_t, double> dpitch;
  };
  std::vector<CameraFolder> cameras;
  for (const std::string& folder : folders) {
    const fs::path dir = fs::path(data_dir) / folder;
    if (!hasGroundTruth(dir)) return out;
    cameras.push_back({folder, dir, readRecording(dir.string()),
                       check.add_fit_dpitch ? fitDpitch(dir) : std::map<std::int64_t, double>{}});
  }
  struct Shot {
    const CameraFolder* camera;
    const FrameRecord* frame;
  };
  std::vector<Shot> shots;  // every frame of every folder, in time order (folders' order on ties)
  for (const CameraFolder& c : cameras) {
    for (const FrameRecord& f : c.recording.frames) shots.push_back({&c, &f});
  }
  std::stable_sort(shots.begin(), shots.end(),
                   [](const Shot& a, const Shot& b) { return a.frame->t_us < b.frame->t_us; });
  const auto cameraId = [&](const Shot& s) {
    return cameras.size() == 1 ? s.frame->camera_id : s.camera->name + "/" + s.frame->camera_id;
  };
  const auto field =
      std::make_shared<const FieldModel>(makeStandardField(realFolderStandard(folders.front())));
  LocalizationPipeline pipeline(PipelineMode::kGlobalOnly, field, config);
  for (const Shot& s : shots)
    pipeline.setCamera(cameraId(s), s.camera->recording.intrinsicsFor(*s.frame));
  const auto pipelineFrame = [&](const Shot& s) {
    PipelineFrame frame;
    frame.t_us = s.frame->t_us;
    frame.camera_id = cameraId(s);
    frame.robot_T_camera = s.frame->robot_T_camera;
    frame.odometry = s.frame->odometry;
    if (const auto d = s.camera->dpitch.find(s.frame->t_us); d != s.camera->dpitch.end())
      frame.robot_T_camera.pitch += d->second;
    return frame;
  };
  const auto readImage = [&](const Shot& s) {
    return cv::imread((s.camera->dir / s.frame->image).string(), cv::IMREAD_COLOR);
  };
  if (check.learn_tilt_first) {
    for (const Shot& s : shots) {
      if (const cv::Mat bgr = readImage(s); !bgr.empty())
        pipeline.learnCameraTilt(pipelineFrame(s), bgr);
    }
  }
  // Every frame in order, as houghloc-offline --global-only runs the folder.
  for (const Shot& s : shots) {
    const PipelineFrame frame = pipelineFrame(s);
    const cv::Mat bgr = readImage(s);
    const SeenFrame seen = bgr.empty() ? pipeline.seeNothing(frame) : pipeline.see(frame, bgr);
    const PipelineResult located = pipeline.locate(seen);
    const std::optional<Pose2> truth =
        groundTruthAt(s.camera->recording.ground_truth, s.frame->t_us);
    if (!truth) continue;
    GlobalCheckFrame r;
    r.folder = s.camera->name;
    r.image = s.frame->image;
    r.t_us = s.frame->t_us;
    r.truth = *truth;
    r.points = static_cast<int>(seen.vision.ground.points.size());
    const Pose2 twin = mirrored(*truth);
    r.nearest_m = std::numeric_limits<double>::quiet_NaN();
    r.nearest_heading_rad = std::numeric_limits<double>::quiet_NaN();
    for (const PoseHypothesis& h : located.global) {
      if (h.kind == HypothesisKind::kHeadingOnly) continue;  // no position (as --global-only)
      const Pose2& pose = h.field_T_robot;
      if (r.hit_rank < 0 && within(pose, *truth, check)) r.hit_rank = r.hypotheses;
      if (r.mirror_hit_rank < 0 && within(pose, twin, check)) r.mirror_hit_rank = r.hypotheses;
      const double d = (pose.translation() - truth->translation()).norm();
      if (std::isnan(r.nearest_m) || d < r.nearest_m) {
        r.nearest_m = d;
        r.nearest_heading_rad = std::abs(angleDifference(pose.theta, truth->theta));
      }
      ++r.hypotheses;
    }
    const CameraModel camera(s.camera->recording.intrinsicsFor(*s.frame), frame.robot_T_camera);
    const std::vector<Eigen::Vector2d> points = robotFramePoints(seen.vision.ground.points);
    r.metrics = groundTruthMetrics(*field, *truth, camera, points);
    if (!check.overlay_dir.empty() && !bgr.empty()) {
      const GroundTruthMetricsConfig metrics;
      const std::string name = s.camera->name + "_" + fs::path(s.frame->image).stem().string();
      writeCoverageOverlay(
          (fs::path(check.overlay_dir) / (name + ".png")).string(), bgr,
          CameraModel(s.camera->recording.intrinsicsFor(*s.frame), seen.vision.robot_T_camera_used),
          visibleLineSamples(*field, *truth, camera, metrics), points, metrics.found_radius_m);
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<std::vector<std::string>> sameRobotFolders(const std::string& data_dir,
                                                       const std::vector<std::string>& folders) {
  std::map<std::string, std::vector<std::string>> by_truth;  // groundtruth.csv's bytes
  for (const std::string& folder : folders) {
    const fs::path file = fs::path(data_dir) / folder / "groundtruth.csv";
    std::ifstream in(file, std::ios::binary);
    if (!in) continue;
    by_truth[std::string(std::istreambuf_iterator<char>(in), {})].push_back(folder);
  }
  std::vector<std::vector<std::string>> groups;
  for (auto& [truth, group] : by_truth) {
    if (group.size() > 1) groups.push_back(std::move(group));
  }
  return groups;
}

}  // namespace houghloc
