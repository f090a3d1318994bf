#include "tools/offline/mode_full.h"

#include <chrono>

#include "tools/offline/localization_run.h"

namespace houghloc {

FullModeLocalizer::FullModeLocalizer(const OfflineContext& context)
    : context_(context), localizer_(requireField(context), context.localizer_config) {}

LocalizationEstimate FullModeLocalizer::process(const FrameRecord& frame,
                                                const GroundPoints& points) {
  // Hints take effect at their time: all of those up to this frame's time, in order.
  while (next_hint_ < context_.hints.size() && context_.hints[next_hint_].t_us <= frame.t_us) {
    localizer_.applyHint(context_.hints[next_hint_++]);
  }
  return localizer_.process(frame.t_us, frame.odometry, {frame.robot_T_camera}, points);
}

FrameEstimate toFrameEstimate(std::int64_t t_us, const LocalizationEstimate& estimate) {
  FrameEstimate out;
  out.t_us = t_us;
  out.status = trackerStatusName(estimate.status);
  for (const EstimateHypothesis& h : estimate.hypotheses) out.hypotheses.push_back(h.pose);
  return out;
}

int runFull(const OfflineContext& context) {
  FullModeLocalizer localizer(context);
  // The track goes back to vision: its pitch/roll corrector matches the points to the map there.
  FieldPoseFeedback feedback(context.first_frame);
  const LocalizationStep step = [&](const VisionFrame& v) {
    LocalizationStepResult r;
    const auto start = std::chrono::steady_clock::now();
    const LocalizationEstimate estimate = localizer.process(*v.frame, v.result.ground);
    r.localization_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    r.global_ms = estimate.global_ms;
    r.global_ran = estimate.global_ran;
    r.estimate = toFrameEstimate(v.frame->t_us, estimate);
    feedback.publish(v.index, v.frame->odometry, estimate);
    return r;
  };
  return runLocalizationMode(context, "houghloc-offline", false, step, &feedback);
}

}  // namespace houghloc
