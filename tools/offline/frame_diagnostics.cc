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
  width_pitch_.add(result.diagnostics.width_pitch_rad);
  field_top_pitch_.add(result.diagnostics.field_top_pitch_rad);
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

void FrameDiagnostics::PitchOffsets::add(double offset_rad) {
  if (offset_rad == 0.0) return;
  const double deg = offset_rad * 180.0 / M_PI;
  min_deg = frames == 0 ? deg : std::min(min_deg, deg);
  max_deg = frames == 0 ? deg : std::max(max_deg, deg);
  ++frames;
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
  if (field_top_pitch_.frames > 0) {
    std::printf(
        "  frames scanned again with the camera pitched further down, as their turf seen above the "
        "computed horizon asks: %d (offset %+.1f to %+.1f deg; the recorded pose may be off)\n",
        field_top_pitch_.frames, field_top_pitch_.min_deg, field_top_pitch_.max_deg);
  }
  if (width_pitch_.frames > 0) {
    std::printf(
        "  frames scanned again with the camera pitch their too-wide candidates ask for: %d "
        "(offset %+.1f to %+.1f deg; the recorded pose may be off)\n",
        width_pitch_.frames, width_pitch_.min_deg, width_pitch_.max_deg);
  }
}

}  // namespace houghloc
