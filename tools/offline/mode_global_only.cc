#include "tools/offline/mode_global_only.h"

#include <cmath>

#include "tools/offline/localization_run.h"
#include "tools/offline/vision_stage.h"

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
  requireField(context);
  const auto pipeline = makePipeline(context, PipelineMode::kGlobalOnly);
  const LocalizationStep step = [&](const VisionFrame& v) {
    const PipelineResult located = pipeline->locate(v.seen);
    LocalizationStepResult r;
    r.global_ms = located.global_ms;
    r.localization_ms = located.localization_ms;
    r.global_ran = true;
    std::vector<PoseHypothesis> placed;  // heading-only hypotheses have no position to write
    double weight_sum = 0.0;
    for (const PoseHypothesis& h : located.global) {
      if (h.kind == HypothesisKind::kHeadingOnly) continue;
      placed.push_back(h);
      weight_sum += h.weight;
    }
    r.estimate.t_us = v.frame->t_us;
    r.estimate.status = globalOnlyStatus(placed);
    for (const PoseHypothesis& h : placed) {
      GaussianPose pose;
      pose.mean = h.field_T_robot;
      pose.covariance = h.covariance;
      pose.weight = weight_sum > 0.0 ? h.weight / weight_sum : 0.0;
      r.estimate.hypotheses.push_back(pose);
    }
    return r;
  };
  return runLocalizationMode(context, *pipeline, "houghloc-offline --global-only", true, step);
}

}  // namespace houghloc
