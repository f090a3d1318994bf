#include "tools/offline/correction_summary.h"

#include <cmath>
#include <cstdio>

namespace houghloc {

void CorrectionSummary::add(const std::string& camera_id, const VisionDiagnostics& diagnostics) {
  Camera& camera = cameras_[camera_id];
  camera.applied = diagnostics.pose_correction_rad;
  camera.applied_per_frame.push_back(camera.applied);
  camera.estimate = diagnostics.pose_correction_estimate_rad;
  camera.sigma = diagnostics.pose_correction_sigma_rad;
  if (diagnostics.pose_correction_map_inliers > 0) ++camera.map_matched_frames;
}

void CorrectionSummary::print() const {
  constexpr double kDeg = 57.29577951308232;
  for (const auto& [id, c] : cameras_) {
    const std::string label = id.empty() ? "" : " (" + id + ")";
    std::printf("  camera correction at the end%s: roll %.3f deg, pitch %.3f deg", label.c_str(),
                c.applied.x() * kDeg, c.applied.y() * kDeg);
    // The estimate before the significance gate: what to add to the calibration's roll and
    // pitch when it is well determined and the recording's calibration is known to be off.
    if (std::isfinite(c.sigma.maxCoeff())) {
      std::printf(" (estimate %.3f +- %.3f, %.3f +- %.3f deg; %d frames matched to the map)",
                  c.estimate.x() * kDeg, c.sigma.x() * kDeg, c.estimate.y() * kDeg,
                  c.sigma.y() * kDeg, c.map_matched_frames);
    }
    std::printf("\n");
    if (const int late = framesFarFromTheFinalCorrection(id); late > 0) {
      std::printf(
          "  %d frames%s ran with a correction more than %.1f deg from this one; "
          "--learn-tilt-first gives every frame the final one (stills, or a pose off from the "
          "start)\n",
          late, label.c_str(), kLateCorrectionRad * kDeg);
    }
  }
}

int CorrectionSummary::framesFarFromTheFinalCorrection(const std::string& camera_id) const {
  const auto camera = cameras_.find(camera_id);
  if (camera == cameras_.end()) return 0;
  int far = 0;
  for (const Eigen::Vector2d& applied : camera->second.applied_per_frame) {
    far += (applied - camera->second.applied).cwiseAbs().maxCoeff() > kLateCorrectionRad;
  }
  return far;
}

}  // namespace houghloc
