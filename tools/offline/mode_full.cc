#include "tools/offline/mode_full.h"

#include "tools/offline/localization_run.h"

namespace houghloc {

FrameEstimate toFrameEstimate(std::int64_t t_us, const LocalizationEstimate& estimate) {
  FrameEstimate out;
  out.t_us = t_us;
  out.status = trackerStatusName(estimate.status);
  for (const EstimateHypothesis& h : estimate.hypotheses) out.hypotheses.push_back(h.pose);
  return out;
}

int runFull(const OfflineContext& context) {
  requireField(context);
  const auto pipeline = makePipeline(context, PipelineMode::kFull);
  const LocalizationStep step = [&](const VisionFrame& v) {
    const PipelineResult located = pipeline->locate(v.seen);
    LocalizationStepResult r;
    r.localization_ms = located.localization_ms;
    r.global_ms = located.global_ms;
    r.global_ran = located.global_ran;
    r.estimate = toFrameEstimate(v.frame->t_us, located.estimate);
    return r;
  };
  return runLocalizationMode(context, *pipeline, "houghloc-offline", false, step);
}

}  // namespace houghloc
