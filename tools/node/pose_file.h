#pragma once

#include <optional>
#include <string>

#include "localization/gaussian_pose.h"

namespace houghloc {

/// houghloc-node --save-pose: the best pose kept across restarts of the node.
struct PoseFileConfig {
  double save_period_s = 1.0;  ///< rewritten this often while TRACKING or AMBIGUOUS, s
  /// The restored pose becomes a RESET_TO hint with these standard deviations: the robot may
  /// have walked for the up to 1 s since the last save and the ~1 s the node needs to start
  /// (NAO: <= 0.3 m/s), and a Gaussian this wide still keeps the hypothesis on its own half.
  double restore_sigma_m = 0.3;
  double restore_sigma_rad = 0.2;
};

/// Writes the pose (mean and covariance) as YAML to `path` atomically: into `path`.tmp, then
/// rename(), so a reader (or a restart after a power cut) sees the old or the new file, never
/// half of one. Throws std::runtime_error naming the file when it cannot be written.
void savePoseFile(const std::string& path, const GaussianPose& field_T_robot);

/// The pose of savePoseFile(); none when the file does not exist (the first start). Throws
/// std::runtime_error naming the file and key for a file that exists but is not such a pose.
std::optional<GaussianPose> loadPoseFile(const std::string& path);

}  // namespace houghloc
