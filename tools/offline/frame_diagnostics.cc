#include "tools/offline/frame_diagnostics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace houghloc {

FrameDiagnostics::FrameDiagnostics(const std::string& spots_csv)
    : spots_(spots_csv, {"t_us", "camera", "u", "v", "width_px", "projected"}) {}

void FrameDiagnostics::add(const FrameRecord& frame, const CameraIntrinsics& intrinsics,
                           const VisionResult& result, const GroundProjectionConfig& projection) {
  ++counts_[static_cast<size_t>(classifyFrame(result))];
  if (const double offset = result.diagnostics.image_pitch_rad; offset != 0.0) {
    const double deg = offset * 180.0 / M_PI;
    image_pitch_min_deg_ = image_pitch_frames_ == 0 ? deg : std::min(image_pitch_min_deg_, deg);
    image_pitch_max_deg_ = image_pitch_frames_ == 0 ? deg : std::max(image_pitch_max_deg_, deg);
    ++image_pitch_frames_;
    if (result.diagnostics.field_top_rescans > 0) ++field_top_frames_;
  }
  const CameraModel camera(intrinsics, result.robot_T_camera_used);
  const std::vector<SpotRay> rays = spotRays(camera, result.spots);
  const GroundProjector projector(result.robot_T_camera_used);
  const std::string camera_id = frame.camera_id.empty() ? "-" : frame.camera_id;
  for (size_t i = 0; i < rays.size(); ++i) {
    const LineSpot& spot = result.spots[i];
    const bool projected = projector.project(rays[i].ray_camera, projection).has_value();
    spots_.writeRow({spots_.format(frame.t_us), camera_id, spots_.format(spot.pixel.x()),
                     spots_.format(spot.pixel.y()), spots_.format(spot.width_px),
                     projected ? "yes" : "no"});
  }
}

void FrameDiagnostics::print() const {
  int without = 0;
  for (int i = 1; i < kNumFrameRejections; ++i) without += counts_[static_cast<size_t>(i)];
  std::printf("  frames without points %d", without);
  const char* separator = ":";
  for (int i = 1; i < kNumFrameRejections; ++i) {
    if (counts_[static_cast<size_t>(i)] == 0) continue;
    std::printf("%s %s %d", separator, frameRejectionName(static_cast<FrameRejection>(i)),
                counts_[static_cast<size_t>(i)]);
    separator = ",";
  }
  std::printf("\n");
  if (image_pitch_frames_ > 0) {
    std::printf(
        "  frames scanned again with the camera pitch the image asks for: %d, %d of them for "
        "field above the horizon (offset %+.1f to %+.1f deg; the recorded pose may be off)\n",
        image_pitch_frames_, field_top_frames_, image_pitch_min_deg_, image_pitch_max_deg_);
  }
}

}  // namespace houghloc
