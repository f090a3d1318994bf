#include "tools/offline/mode_global_only.h"

#include <chrono>
#include <cmath>

#include "localization/global_hough_localizer.h"
#include "tools/offline/localization_run.h"

namespace houghloc {

const char* globalOnlyStatus(const std::vector<PoseHypothesis>& hypotheses,
                             const GlobalStatusConfig& config) {
  if (hypotheses.empty()) return "LOST";
  if (hypotheses.size() < 2) return "TRACKING";
  const PoseHypothesis& best = hypotheses[0];
  const PoseHypothesis& second = hypotheses[1];
  if (second.weight < config.comparable_weight_ratio * best.weight) return "TRACKING";
  const bool same = (best.field_T_robot.translation() - second.field_T_robot.translation()).norm() <
                        config.same_position_m &&
                    std::abs(angleDifference(best.field_T_robot.theta,
                                             second.field_T_robot.theta)) < config.same_heading_rad;
  return same ? "TRACKING" : "AMBIGUOUS";
}

int runGlobalOnly(const OfflineContext& context) {
  const GlobalHoughLocalizer localizer(requireField(context), context.localizer_config.global);
  const LocalizationStep step = [&](const VisionFrame& v) {
    LocalizationStepResult r;
    const auto start = std::chrono::steady_clock::now();
    std::vector<PoseHypothesis> found = localizer.locate(v.result.ground);
    r.global_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    r.localization_ms = r.global_ms;
    r.global_ran = true;
    std::vector<PoseHypothesis> located;
    double weight_sum = 0.0;
    for (const PoseHypothesis& h : found) {
      if (h.kind == HypothesisKind::kHeadingOnly) continue;
      located.push_back(h);
      weight_sum += h.weight;
    }
    r.estimate.t_us = v.frame->t_us;
    r.estimate.status = globalOnlyStatus(located);
    for (const PoseHypothesis& h : located) {
      GaussianPose pose;
      pose.mean = h.field_T_robot;
      pose.covariance = h.covariance;
      pose.weight = weight_sum > 0.0 ? h.weight / weight_sum : 0.0;
      r.estimate.hypotheses.push_back(pose);
    }
    return r;
  };
  return runLocalizationMode(context, "houghloc-offline --global-only", true, step);
}

}  // namespace houghloc
