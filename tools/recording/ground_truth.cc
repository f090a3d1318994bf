// groundTruthAt() and Recording::intrinsicsFor().
#include <algorithm>
#include <cmath>

#include "tools/recording/recording.h"

namespace houghloc {

const CameraIntrinsics& Recording::intrinsicsFor(const FrameRecord& frame) const {
  if (frame.camera_id.empty()) {
    if (!camera) throw RecordingError(folder + "/camera.yaml: missing camera file");
    return *camera;
  }
  const auto it = cameras.find(frame.camera_id);
  if (it == cameras.end()) {
    throw RecordingError(folder + "/cameras/" + frame.camera_id + ".yaml: missing camera file");
  }
  return it->second;
}

// Interpolates only between two rows that are both within the tolerance, so a gap in the
// ground truth is never bridged; otherwise the nearest row within the tolerance is used.
std::optional<Pose2> groundTruthAt(const std::vector<GroundTruthRecord>& truth, std::int64_t t_us,
                                   std::int64_t tolerance_us) {
  const auto after =
      std::lower_bound(truth.begin(), truth.end(), t_us,
                       [](const GroundTruthRecord& r, std::int64_t t) { return r.t_us < t; });
  // Distances in double: timestamps near the int64 limits must not overflow.
  auto within = [&](const GroundTruthRecord& r) {
    return std::abs(static_cast<double>(r.t_us) - static_cast<double>(t_us)) <=
           static_cast<double>(tolerance_us);
  };
  const bool has_after = after != truth.end();
  const bool has_before = after != truth.begin();
  if (has_after && after->t_us == t_us) return after->field_T_robot;
  const bool after_ok = has_after && within(*after);
  const bool before_ok = has_before && within(*std::prev(after));
  if (after_ok && before_ok) {
    const GroundTruthRecord& a = *std::prev(after);
    const GroundTruthRecord& b = *after;
    const double s = (static_cast<double>(t_us) - static_cast<double>(a.t_us)) /
                     (static_cast<double>(b.t_us) - static_cast<double>(a.t_us));
    const Pose2& p = a.field_T_robot;
    const Pose2& q = b.field_T_robot;
    return Pose2(p.x + s * (q.x - p.x), p.y + s * (q.y - p.y),
                 p.theta + s * angleDifference(q.theta, p.theta));
  }
  if (before_ok) return std::prev(after)->field_T_robot;
  if (after_ok) return after->field_T_robot;
  return std::nullopt;
}

}  // namespace houghloc
