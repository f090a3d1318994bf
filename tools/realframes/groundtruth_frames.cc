#include "tools/realframes/groundtruth_frames.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <opencv2/imgcodecs.hpp>

#include "field_models/standard_fields.h"
#include "localization/gaussian_pose.h"
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
  const fs::path dir = fs::path(data_dir) / folder;
  std::vector<GlobalCheckFrame> out;
  if (!hasGroundTruth(dir)) return out;
  const Recording recording = readRecording(dir.string());
  const auto field =
      std::make_shared<const FieldModel>(makeStandardField(realFolderStandard(folder)));
  const std::map<std::int64_t, double> dpitch =
      check.add_fit_dpitch ? fitDpitch(dir) : std::map<std::int64_t, double>{};
  LocalizationPipeline pipeline(PipelineMode::kGlobalOnly, field, config);
  for (const FrameRecord& f : recording.frames)
    pipeline.setCamera(f.camera_id, recording.intrinsicsFor(f));
  const auto pipelineFrame = [&](const FrameRecord& f) {
    PipelineFrame frame;
    frame.t_us = f.t_us;
    frame.camera_id = f.camera_id;
    frame.robot_T_camera = f.robot_T_camera;
    frame.odometry = f.odometry;
    if (const auto d = dpitch.find(f.t_us); d != dpitch.end())
      frame.robot_T_camera.pitch += d->second;
    return frame;
  };
  const auto readImage = [&](const FrameRecord& f) {
    return cv::imread((dir / f.image).string(), cv::IMREAD_COLOR);
  };
  if (check.learn_tilt_first) {
    for (const FrameRecord& f : recording.frames) {
      if (const cv::Mat bgr = readImage(f); !bgr.empty())
        pipeline.learnCameraTilt(pipelineFrame(f), bgr);
    }
  }
  // Every frame in order, as houghloc-offline --global-only runs the folder.
  for (const FrameRecord& f : recording.frames) {
    const PipelineFrame frame = pipelineFrame(f);
    const cv::Mat bgr = readImage(f);
    const SeenFrame seen = bgr.empty() ? pipeline.seeNothing(frame) : pipeline.see(frame, bgr);
    const PipelineResult located = pipeline.locate(seen);
    const std::optional<Pose2> truth = groundTruthAt(recording.ground_truth, f.t_us);
    if (!truth) continue;
    GlobalCheckFrame r;
    r.image = f.image;
    r.t_us = f.t_us;
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
    const CameraModel camera(recording.intrinsicsFor(f), frame.robot_T_camera);
    r.metrics =
        groundTruthMetrics(*field, *truth, camera, robotFramePoints(seen.vision.ground.points));
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace houghloc
