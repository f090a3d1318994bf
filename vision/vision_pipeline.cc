#include "vision/vision_pipeline.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "vision/boundary_gap.h"
#include "vision/isolated_spots.h"
#include "vision/pixel_access.h"

namespace houghloc {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point* start) {
  const Clock::time_point now = Clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - *start).count();
  *start = now;
  return ms;
}

bool samePose(const Pose3& a, const Pose3& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z && a.roll == b.roll && a.pitch == b.pitch &&
         a.yaw == b.yaw;
}

CameraPoseCorrectionConfig correctorConfig(const VisionConfig& config) {
  CameraPoseCorrectionConfig out = config.pose_correction;
  out.circle_radius_m = config.segments.circle_radius_m;  // the map's centre circle
  return out;
}

}  // namespace

VisionPipeline::VisionPipeline(const CameraIntrinsics& intrinsics, const VisionConfig& config,
                               int camera_id)
    : config_(config),
      camera_id_(camera_id),
      camera_(intrinsics, Pose3{}),
      corrector_(std::make_shared<CameraPoseCorrector>(correctorConfig(config))) {}

VisionResult VisionPipeline::process(const cv::Mat& image, const Pose3& robot_T_camera,
                                     std::int64_t t_us, const std::optional<Pose2>& field_T_robot) {
  if (!robot_T_camera.isFinite()) {
    throw std::invalid_argument("robot_T_camera is not finite (NaN or infinite component)");
  }
  if (image.cols != camera_.width() || image.rows != camera_.height()) {
    throw std::invalid_argument("image is " + std::to_string(image.cols) + "x" +
                                std::to_string(image.rows) + " but the camera is " +
                                std::to_string(camera_.width()) + "x" +
                                std::to_string(camera_.height()));
  }
  Clock::time_point start = Clock::now(), step = start;
  VisionResult result;
  VisionDiagnostics& diag = result.diagnostics;
  result.ground.t_us = t_us;
  // The stages read BGR8 in place and decode only the YUYV pixels they read (pixel_access.h).
  checkPixelLayout(image);

  // 1. Horizon from the (corrected) camera pose.
  Pose3 recorded = robot_T_camera;
  Pose3 pose = corrector_->corrected(recorded);
  usePose(pose, &result);
  std::vector<int> start_rows = scanStartRows(camera_, config_.horizon);
  // 2-3. Field colour from this frame, then the field boundary.
  const bool remembered = field_color_age_ <= config_.field_color.memory_frames;
  diag.field_color = estimateFieldColor(image, start_rows, config_.field_color,
                                        remembered ? &last_field_color_ : nullptr);
  if (diag.field_color.valid) {
    last_field_color_ = diag.field_color;
    field_color_age_ = 0;
  } else if (field_color_age_ <= config_.field_color.memory_frames) {
    ++field_color_age_;
  }
  diag.time_color_ms = msSince(&step);

  // 3-4. The field boundary, then line spots on a distance-adapted scan grid below it; 5-6.
  // the spots undistorted, and the segments and circles they form.
  findSpots(image, start_rows, &result);
  diag.time_spots_ms = msSince(&step);
  std::vector<SpotRay> all_rays = fitFeatures(pose, &result);
  diag.time_features_ms = msSince(&step);
  // Beyond the recorded pose: a frame whose spots form no line is scanned again as if recorded
  // with the pitch its image asks for. Such a rescan can leave the frame without spots but with
  // candidates whose widths tell the pitch, hence more than one.
  constexpr int kMaxPitchRescans = 3;
  double shortfall = 0.0;  // how much steeper than the pose's pitch the camera may look (rad)
  for (int rescan = 0; rescan < kMaxPitchRescans && !formsLines(result.features); ++rescan) {
    const std::optional<PitchRequest> request = pitchTheImageAsksFor(image, result, start_rows);
    if (!request) break;
    addPitch(request->offset_rad, &recorded, &pose, &start_rows, &result);
    diag.spot_stats = LineSpotStats{};  // the new scan's
    // The field top gives a lower bound on the pitch (field_top_pitch.h), the widths a fit.
    const bool bound = request->diagnostic == &VisionDiagnostics::field_top_pitch_rad;
    shortfall = bound ? config_.field_top_pitch.max_shortfall_rad : 0.0;
    findSpots(image, start_rows, &result, shortfall);
    all_rays = fitFeatures(pose, &result);
    diag.*(request->diagnostic) += request->offset_rad;
  }
  // Lines found with a bound's pitch: their widths tell where in the shortfall the pitch lies
  // (the points would otherwise lie too far by the shortfall's share of their depression).
  if (shortfall > 0.0 && formsLines(result.features)) {
    const double more = fitPitchAboveBound(camera_, result.spots, shortfall, config_.width_pitch);
    if (more > 0.0) {
      addPitch(more, &recorded, &pose, &start_rows, &result);
      diag.spot_stats = LineSpotStats{};
      findSpots(image, start_rows, &result, shortfall - more);
      all_rays = fitFeatures(pose, &result);
      diag.field_top_pitch_rad += more;
    }
  }
  diag.num_spots = static_cast<int>(result.spots.size());
  diag.time_spots_ms += msSince(&step);  // the rescans

  // 6. The pitch/roll correction, which then applies to this frame's projection already.
  // A frame processed with a pitch its image asked for does not teach the corrector: it
  // estimates the recorded poses' error, and would learn that of the image's rough pitch instead
  // (and pass it on to frames that need none).
  const bool recorded_pitch = diag.field_top_pitch_rad == 0.0 && diag.width_pitch_rad == 0.0;
  if (recorded_pitch) {
    diag.pose_correction_updated = corrector_->update(
        result.features.segments, result.features.circles, recorded, {&all_rays, field_T_robot});
  }
  const Pose3 refined = corrector_->corrected(recorded);
  if (!samePose(refined, pose)) {
    result.robot_T_camera_used = refined;
    // The horizon and the visible region follow only noticeable changes (setPose recomputes
    // the horizon per column); the points below use the refined pose exactly.
    if (std::abs(refined.pitch - pose.pitch) + std::abs(refined.roll - pose.roll) > 1e-3) {
      camera_.setPose(refined);
      result.horizon_rows = camera_.horizonRows();
    }
  }
  std::vector<SpotRay> rays = dropSpotsNearBoundary(
      all_rays, camera_, result.boundary, start_rows, config_.projection.min_boundary_gap_m,
      config_.projection.min_boundary_gap_range_m, &diag.dropped_near_boundary);
  diag.dropped_isolated = dropIsolated(&rays, config_.spots.support);
  if (diag.dropped_near_boundary > 0 || diag.dropped_isolated > 0 || !samePose(refined, pose)) {
    result.features = fitLineFeatures(rays, refined, config_.projection, config_.segments);
  }
  diag.pose_correction_rad = {refined.roll - recorded.roll, refined.pitch - recorded.pitch};
  diag.pose_correction_estimate_rad = corrector_->estimate();
  diag.pose_correction_sigma_rad = corrector_->estimateSigma();
  diag.pose_correction_map_inliers = corrector_->lastMapInliers();
  diag.time_features_ms += msSince(&step);

  result.ground.points = projectSpots(rays, result.robot_T_camera_used, camera_id_,
                                      config_.projection, &diag.projection_stats);
  GroundPolygon region = visibleRegion(camera_, result.boundary, config_.projection);
  if (!region.empty()) result.ground.visible_regions.push_back(std::move(region));
  result.ground.field_edge =
      fieldEdgePoints(camera_, result.boundary, start_rows, camera_id_, config_.field_edge);
  diag.time_project_ms += msSince(&step);
  diag.time_total_ms = msSince(&start);
  return result;
}

void VisionPipeline::usePose(const Pose3& pose, VisionResult* result) {
  if (!samePose(pose, camera_.pose())) camera_.setPose(pose);
  result->robot_T_camera_used = pose;
  result->horizon_rows = camera_.horizonRows();
}

void VisionPipeline::addPitch(double offset, Pose3* recorded, Pose3* pose,
                              std::vector<int>* start_rows, VisionResult* result) {
  recorded->pitch += offset;
  *pose = corrector_->corrected(*recorded);
  usePose(*pose, result);
  *start_rows = scanStartRows(camera_, config_.horizon);
}

std::optional<VisionPipeline::PitchRequest> VisionPipeline::pitchTheImageAsksFor(
    const cv::Mat& image, const VisionResult& result, const std::vector<int>& start_rows) const {
  const VisionDiagnostics& diag = result.diagnostics;
  // On a frame without spots, the pitch its too-wide candidates' widths ask for (width_pitch.h);
  // where other candidates fit the width model, too-wide ones are more likely feet, a ball or a
  // robot close by.
  if (result.spots.empty()) {
    const std::optional<double> offset = fitPitchToWidths(camera_, diag.spot_stats.too_wide_runs,
                                                          config_.spots, config_.width_pitch);
    if (offset) return PitchRequest{*offset, &VisionDiagnostics::width_pitch_rad};
  }
  // Turf seen above the computed horizon: the camera looks further down than the pose says
  // (field_top_pitch.h).
  const std::optional<double> offset =
      pitchToSeeFieldTop(image, diag.field_color, camera_, start_rows, config_.field_top_pitch);
  if (offset) return PitchRequest{*offset, &VisionDiagnostics::field_top_pitch_rad};
  return std::nullopt;
}

std::vector<SpotRay> VisionPipeline::fitFeatures(const Pose3& pose, VisionResult* result) const {
  // The corrector sees all spots but those on the robot's own feet: the goal frame's bars
  // dropped below are parallel or perpendicular to the lines anyway, and with a wrong tilt the
  // boundary gap would be measured wrongly.
  std::vector<SpotRay> rays =
      dropSpotsOnOwnBody(spotRays(camera_, result->spots), pose, config_.own_body,
                         &result->diagnostics.dropped_on_own_body);
  result->features = fitLineFeatures(rays, pose, config_.projection, config_.segments);
  return rays;
}

bool VisionPipeline::formsLines(const LineFeatures& features) {
  return !features.segments.empty() || !features.circles.empty();
}

void VisionPipeline::findSpots(const cv::Mat& image, const std::vector<int>& start_rows,
                               VisionResult* result, double pitch_shortfall_rad) const {
  VisionDiagnostics& diag = result->diagnostics;
  result->boundary = detectFieldBoundary(image, diag.field_color, start_rows, config_.boundary);
  const LineWidthModel widths(camera_, config_.line_width_m, config_.line_width);
  const ScanGrid grid = makeScanGrid(camera_, widths, result->boundary, config_.scan_grid);
  std::optional<LineWidthModel> widest;
  if (pitch_shortfall_rad > 0.0) {
    Pose3 steeper = camera_.pose();
    steeper.pitch += pitch_shortfall_rad;
    widest.emplace(CameraModel(camera_.intrinsics(), steeper, camera_.config()),
                   config_.line_width_m, config_.line_width);
  }
  result->spots = detectLineSpots(image, diag.field_color, result->boundary, grid, widths,
                                  config_.spots, &diag.spot_stats, widest ? &*widest : nullptr);
}

}  // namespace houghloc
