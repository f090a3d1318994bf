#pragma once

#include <Eigen/Core>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "vision/vision_pipeline.h"

namespace houghloc {

/// The pitch/roll corrector after each camera's last processed frame, for the run summaries:
/// with a NAO's two cameras each has its own corrector (unless shared_between_cameras), and the
/// bottom one alone is never corrected, so one line per camera.
class CorrectionSummary {
 public:
  /// One processed frame of `camera_id` ("" for a recording with one camera.yaml).
  void add(const std::string& camera_id, const VisionDiagnostics& diagnostics);

  /// "  camera correction at the end[ (id)]: roll R deg, pitch P deg (estimate R +- s, P +- s
  /// deg; N frames matched to the map)" per camera, the estimate once there is one; then, when
  /// frames ran with a correction that differs from the final one by more than
  /// kLateCorrectionRad in roll or pitch, how many (--learn-tilt-first gives them the final one).
  void print() const;

  static constexpr double kLateCorrectionRad = 0.5 * 3.14159265358979323846 / 180.0;

  /// Frames of `camera_id` whose applied correction differed from the last one by more than
  /// kLateCorrectionRad.
  int framesFarFromTheFinalCorrection(const std::string& camera_id) const;

 private:
  struct Camera {
    std::vector<Eigen::Vector2d> applied_per_frame;      ///< rad, in frame order
    Eigen::Vector2d applied = Eigen::Vector2d::Zero();   ///< rad
    Eigen::Vector2d estimate = Eigen::Vector2d::Zero();  ///< before the significance gate, rad
    Eigen::Vector2d sigma = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    int map_matched_frames = 0;  ///< frames whose points were matched to the map
  };
  std::map<std::string, Camera> cameras_;
};

}  // namespace houghloc
