#pragma once

#include <cstdint>

#include "localization/localizer.h"
#include "tools/offline/estimate_csv.h"
#include "tools/offline/offline_context.h"

namespace houghloc {

/// An estimate as poses.csv and hypotheses.csv hold it.
FrameEstimate toFrameEstimate(std::int64_t t_us, const LocalizationEstimate& estimate);

/// The full mode (DESIGN §5.2): LocalizationPipeline in PipelineMode::kFull frame by frame, with
/// the odometry and camera pose of frames.csv and the hints of hints.csv, each applied before
/// the first frame whose t_us is at or after the hint's. A frame whose image is missing goes to
/// the localizer without points (prediction only). Writes poses.csv, hypotheses.csv, timing.csv
/// (points.csv with --points), the `tracking` section of metrics.json and trajectory.png.
/// Returns the exit code; throws for input and output errors.
int runFull(const OfflineContext& context);

}  // namespace houghloc
