#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "vision/frame_rejection.h"
#include "vision/vision_pipeline.h"

namespace houghloc {

/// The points' positions in the robot frame (m), in their order.
std::vector<Eigen::Vector2d> robotFramePoints(const std::vector<GroundPoint>& points);

/// One row of the real set's index.csv: whether the frame shows field lines (judged by eye).
struct RealFrameLabel {
  std::string folder, image;
  std::int64_t t_us = 0;
  std::string lines_visible;  ///< yes, faint or no
  bool has_mask = false;
};

/// Reads <data_dir>/index.csv; throws RecordingError naming file and line on malformed rows.
std::vector<RealFrameLabel> readRealIndex(const std::string& data_dir);

/// What one frame gave: houghloc's ground points and the naive column scan's, both projected
/// with the recorded camera pose and the same range limits.
struct RealFrameOutcome {
  RealFrameLabel label;
  int points = 0;
  int baseline_points = 0;
  std::vector<Eigen::Vector2f> point_pixels;     ///< houghloc's projected points' pixels
  std::vector<Eigen::Vector2f> baseline_pixels;  ///< the column scan's projected points' pixels
  std::vector<Eigen::Vector2d> points_robot;     ///< houghloc's ground points (robot frame, m)
  std::vector<Eigen::Vector2d> baseline_robot;   ///< the column scan's (robot frame, m)
  VisionDiagnostics diagnostics;
  FrameRejection rejection = FrameRejection::kNone;
};

/// The field standard a folder of the real set is run with (spl, kid or msl), from its name.
std::string realFolderStandard(const std::string& folder);

/// Runs every frame of <data_dir>/<folder> through one VisionPipeline per camera (the recorded
/// poses; line width and circle radius from the folder's standard field) and the column scan.
/// Frames whose image is missing are skipped. Throws RecordingError on a malformed folder.
std::vector<RealFrameOutcome> runRealFolder(const std::string& data_dir,
                                            const std::vector<RealFrameLabel>& labels,
                                            const std::string& folder,
                                            const VisionConfig& base_config = {});

}  // namespace houghloc
