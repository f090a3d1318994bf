#pragma once

#include "tools/offline/offline_context.h"

namespace houghloc {

/// The full mode (DESIGN §5.2, issue 7): vision and the Localizer facade frame by frame, with the
/// odometry and camera pose of frames.csv and the hints of hints.csv, each applied before the
/// first frame whose t_us is at or after the hint's. A frame whose image is missing goes to the
/// localizer without points (prediction only). Writes poses.csv, hypotheses.csv, timing.csv
/// (points.csv with --points), the `tracking` section of metrics.json and trajectory.png.
/// Returns the exit code; throws for input and output errors.
int runFull(const OfflineContext& context);

}  // namespace houghloc
