#include "tools/offline/mode_full.h"

#include <chrono>

#include "localization/localizer.h"
#include "tools/offline/localization_run.h"

namespace houghloc {

int runFull(const OfflineContext& context) {
  Localizer localizer(requireField(context), context.localizer_config);
  size_t next_hint = 0;
  const LocalizationStep step = [&](const VisionFrame& v) {
    LocalizationStepResult r;
    const auto start = std::chrono::steady_clock::now();
    // Hints take effect at their time: all of those up to this frame's time, in order.
    while (next_hint < context.hints.size() && context.hints[next_hint].t_us <= v.frame->t_us) {
      localizer.applyHint(context.hints[next_hint++]);
    }
    const LocalizationEstimate estimate = localizer.process(
        v.frame->t_us, v.frame->odometry, {v.frame->robot_T_camera}, v.result.ground);
    r.localization_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    r.global_ms = estimate.global_ms;
    r.global_ran = estimate.global_ran;
    r.estimate.t_us = v.frame->t_us;
    r.estimate.status = trackerStatusName(estimate.status);
    for (const EstimateHypothesis& h : estimate.hypotheses) {
      r.estimate.hypotheses.push_back(h.pose);
    }
    return r;
  };
  return runLocalizationMode(context, "houghloc-offline", false, step);
}

}  // namespace houghloc
