#pragma once

#include <cstddef>
#include <cstdint>

#include "localization/localizer.h"
#include "tools/offline/estimate_csv.h"
#include "tools/offline/offline_context.h"

namespace houghloc {

/// The full mode's localization of one frame at a time: the hints of hints.csv that are due by
/// the frame's t_us (in order), then Localizer::process with the frame's odometry and camera
/// pose. houghloc-bench-tracking uses it too, so the bench runs the Localizer exactly as
/// houghloc-offline does.
class FullModeLocalizer {
 public:
  /// Needs the context's field (requireField); keeps a reference to the context.
  explicit FullModeLocalizer(const OfflineContext& context);

  LocalizationEstimate process(const FrameRecord& frame, const GroundPoints& points);

 private:
  const OfflineContext& context_;
  Localizer localizer_;
  std::size_t next_hint_ = 0;
};

/// An estimate as poses.csv and hypotheses.csv hold it.
FrameEstimate toFrameEstimate(std::int64_t t_us, const LocalizationEstimate& estimate);

/// The full mode (DESIGN §5.2, issue 7): vision and the Localizer facade frame by frame, with the
/// odometry and camera pose of frames.csv and the hints of hints.csv, each applied before the
/// first frame whose t_us is at or after the hint's. A frame whose image is missing goes to the
/// localizer without points (prediction only). Writes poses.csv, hypotheses.csv, timing.csv
/// (points.csv with --points), the `tracking` section of metrics.json and trajectory.png.
/// Returns the exit code; throws for input and output errors.
int runFull(const OfflineContext& context);

}  // namespace houghloc
