#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "field_models/pose2.h"
#include "tools/pipeline/localization_pipeline.h"
#include "tools/realframes/groundtruth_metrics.h"
#include "tools/realframes/real_frames.h"

namespace houghloc {

/// One real frame that shows lines (index.csv: yes) and has a groundtruth.csv pose, scored at the
/// recorded camera pose: houghloc's points beside the column-scan baseline's.
struct GroundTruthFrameReport {
  std::string folder, image;
  std::int64_t t_us = 0;
  Pose2 field_T_robot;
  GroundTruthMetrics houghloc, baseline;
};

/// The scored frames of a folder from runRealFolder()'s outcomes (the folder's standard field;
/// ground truth by groundTruthAt()). None when the folder has no groundtruth.csv. Throws
/// RecordingError on a malformed folder.
std::vector<GroundTruthFrameReport> groundTruthFrames(const std::string& data_dir,
                                                      const std::string& folder,
                                                      const std::vector<RealFrameOutcome>& outcomes,
                                                      const GroundTruthMetricsConfig& config = {});

/// When a --global-only hypothesis counts as the ground-truth pose.
struct GlobalCheckConfig {
  double position_m = 0.15;
  double heading_rad = 5.0 * M_PI / 180.0;
  /// Add frames.csv's fit_dpitch (physar: the pitch the images want on top of the recorded
  /// chain) to each frame's camera pitch; frames without one keep the recorded pitch.
  bool add_fit_dpitch = false;
  /// Run the vision over the folder once first (LocalizationPipeline::learnCameraTilt), as
  /// houghloc-offline --learn-tilt-first does: every frame starts from the folder's tilt.
  bool learn_tilt_first = false;
  /// When set, each ground-truth frame's coverage overlay (coverage_overlay.h) is written to
  /// <overlay_dir>/<folder>_<image stem>.png.
  std::string overlay_dir;
};

/// One ground-truth frame through LocalizationPipeline in kGlobalOnly mode (as houghloc-offline
/// --global-only runs it): its positioned hypotheses (heading-only ones are left out, as there).
struct GlobalCheckFrame {
  std::string folder, image;
  std::int64_t t_us = 0;
  Pose2 truth;
  int points = 0;
  int hypotheses = 0;
  int hit_rank = -1;         ///< first hypothesis within tolerance of the truth; -1 none
  int mirror_hit_rank = -1;  ///< ... of the mirrored truth (-x, -y, theta + pi)
  double nearest_m = 0.0;    ///< position error of the hypothesis nearest the truth (NaN: none)
  double nearest_heading_rad = 0.0;  ///< its heading error
  GroundTruthMetrics metrics;        ///< the pipeline's points at the camera pose used (see above)
};

/// Whether <data_dir>/<folder> has groundtruth.csv, and whether its frames.csv gives a fit_dpitch.
bool folderHasGroundTruth(const std::string& data_dir, const std::string& folder);
bool folderHasFitDpitch(const std::string& data_dir, const std::string& folder);

/// Runs every frame of <data_dir>/<folder> in order (the folder's standard field, config's
/// vision and localizer sections) and reports those with a ground-truth pose. Throws
/// RecordingError on a malformed folder.
std::vector<GlobalCheckFrame> globalCheckAtGroundTruth(const std::string& data_dir,
                                                       const std::string& folder,
                                                       const PipelineConfig& config,
                                                       const GlobalCheckConfig& check = {});

/// The same for the folders of one robot's cameras taken at the same moments (physar_nao_top and
/// physar_nao_bottom: one top and one bottom image per spot): their frames in time order
/// through one pipeline, each folder a camera (its own camera.yaml), so that with
/// `vision: pose_correction: shared_between_cameras` the cameras share one pitch/roll
/// corrector, as on the robot. The field is the first folder's standard.
std::vector<GlobalCheckFrame> globalCheckAtGroundTruth(const std::string& data_dir,
                                                       const std::vector<std::string>& folders,
                                                       const PipelineConfig& config,
                                                       const GlobalCheckConfig& check = {});

/// Groups of folders with groundtruth.csv that are one robot's cameras: byte-equal
/// groundtruth.csv files (the same spots at the same t_us). Groups of one are left out.
std::vector<std::vector<std::string>> sameRobotFolders(const std::string& data_dir,
                                                       const std::vector<std::string>& folders);

}  // namespace houghloc
