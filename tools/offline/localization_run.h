#pragma once

#include <functional>
#include <string>

#include "tools/offline/estimate_csv.h"
#include "tools/offline/offline_context.h"
#include "tools/offline/vision_stage.h"

namespace houghloc {

/// What a localization mode made of one frame after vision.
struct LocalizationStepResult {
  FrameEstimate estimate;
  double localization_ms = 0.0;  ///< wall time of the whole localization step
  double global_ms = 0.0;        ///< of which the global localizer
  bool global_ran = false;
};

/// Called once per frame in frame order (a skipped frame comes with no points).
using LocalizationStep = std::function<LocalizationStepResult(const VisionFrame&)>;

/// The frame loop both localization modes share: vision (one or two threads), `step`, then
/// poses.csv and hypotheses.csv (EstimateCsvWriter), points.csv with --points, timing.csv,
/// overlays and the video, progress on stderr, the summary table, and finally
/// evaluateOutputs() + printEvaluation() (metrics.json, trajectory.png). Needs a field.
/// Returns the exit code; throws for input and output errors (messages name the file).
/// `pipeline` runs the vision half; `step` calls its localization half.
int runLocalizationMode(const OfflineContext& context, LocalizationPipeline& pipeline,
                        const std::string& title, bool global_only, const LocalizationStep& step);

/// Throws std::runtime_error explaining how to give a field when the context has none.
const FieldModel& requireField(const OfflineContext& context);

}  // namespace houghloc
