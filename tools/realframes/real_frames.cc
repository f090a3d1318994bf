#include "tools/realframes/real_frames.h"

#include <filesystem>
#include <map>
#include <opencv2/imgcodecs.hpp>

#include "field_models/standard_fields.h"
#include "tools/baselines/column_scan.h"
#include "tools/recording/csv.h"
#include "tools/recording/recording.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

std::vector<Eigen::Vector2f> pixelsOf(const std::vector<GroundPoint>& points) {
  std::vector<Eigen::Vector2f> out;
  out.reserve(points.size());
  for (const GroundPoint& p : points) out.push_back(p.pixel);
  return out;
}

VisionConfig configFor(const std::string& folder, const VisionConfig& base) {
  VisionConfig config = base;
  const FieldModel field = makeStandardField(realFolderStandard(folder));
  config.line_width_m = field.line_width;
  for (const Arc2& arc : field.arcs) {
    if (arc.isFullCircle() && arc.center.norm() < 1e-6)
      config.segments.circle_radius_m = arc.radius;
  }
  return config;
}

}  // namespace

std::vector<Eigen::Vector2d> robotFramePoints(const std::vector<GroundPoint>& points) {
  std::vector<Eigen::Vector2d> out;
  out.reserve(points.size());
  for (const GroundPoint& p : points) out.push_back(p.p_robot);
  return out;
}

std::vector<RealFrameLabel> readRealIndex(const std::string& data_dir) {
  const CsvTable table = CsvTable::read((fs::path(data_dir) / "index.csv").string());
  const int folder = table.column("folder"), image = table.column("image"),
            t_us = table.column("t_us"), lines = table.column("lines_visible"),
            mask = table.column("has_mask");
  std::vector<RealFrameLabel> labels;
  for (const CsvRow& row : table.rows()) {
    RealFrameLabel label;
    label.folder = CsvTable::text(row, folder);
    label.image = CsvTable::text(row, image);
    label.t_us = table.integer(row, t_us);
    label.lines_visible = CsvTable::text(row, lines);
    label.has_mask = CsvTable::text(row, mask) == "yes";
    if (label.lines_visible != "yes" && label.lines_visible != "faint" &&
        label.lines_visible != "no") {
      throw RecordingError(table.path() + ":" + std::to_string(row.line) +
                           ": lines_visible must be yes, faint or no");
    }
    labels.push_back(std::move(label));
  }
  return labels;
}

std::string realFolderStandard(const std::string& folder) {
  if (folder.rfind("msl_", 0) == 0) return "msl";
  if (folder.find("kid") != std::string::npos) return "kid";
  return "spl";
}

std::vector<RealFrameOutcome> runRealFolder(const std::string& data_dir,
                                            const std::vector<RealFrameLabel>& labels,
                                            const std::string& folder,
                                            const VisionConfig& base_config) {
  const fs::path dir = fs::path(data_dir) / folder;
  const Recording recording = readRecording(dir.string());
  const VisionConfig config = configFor(folder, base_config);
  std::map<std::int64_t, const RealFrameLabel*> by_time;
  for (const RealFrameLabel& label : labels) {
    if (label.folder == folder) by_time[label.t_us] = &label;
  }
  std::map<std::string, std::unique_ptr<VisionPipeline>> pipelines;
  std::vector<RealFrameOutcome> outcomes;
  for (const FrameRecord& frame : recording.frames) {
    const cv::Mat bgr = cv::imread((dir / frame.image).string(), cv::IMREAD_COLOR);
    if (bgr.empty()) continue;
    std::unique_ptr<VisionPipeline>& pipeline = pipelines[frame.camera_id];
    if (!pipeline) {
      pipeline = std::make_unique<VisionPipeline>(recording.intrinsicsFor(frame), config);
    }
    const VisionResult result = pipeline->process(bgr, frame.robot_T_camera, frame.t_us);
    RealFrameOutcome outcome;
    const auto label = by_time.find(frame.t_us);
    if (label != by_time.end()) outcome.label = *label->second;
    outcome.label.folder = folder;
    outcome.label.t_us = frame.t_us;
    outcome.points = static_cast<int>(result.ground.points.size());
    outcome.point_pixels = pixelsOf(result.ground.points);
    outcome.points_robot = robotFramePoints(result.ground.points);
    outcome.diagnostics = result.diagnostics;
    outcome.rejection = classifyFrame(result);
    // The naive reference, projected like houghloc's spots with the recorded pose.
    const std::vector<GroundPoint> baseline =
        projectSpots(spotRays(pipeline->camera(), columnScanSpots(bgr)), frame.robot_T_camera, 0,
                     config.projection);
    outcome.baseline_points = static_cast<int>(baseline.size());
    outcome.baseline_pixels = pixelsOf(baseline);
    outcome.baseline_robot = robotFramePoints(baseline);
    outcomes.push_back(std::move(outcome));
  }
  return outcomes;
}

}  // namespace houghloc
