// HypothesisTracker::applyHint: DESIGN §7 hints, kept apart from the filter itself.
#include "localization/hypothesis_tracker.h"

namespace houghloc {

void HypothesisTracker::applyHint(const LocalizationHint& hint) {
  switch (hint.kind) {
    case HintKind::kUnknown:
      // Nothing we hold can be trusted: start over from global hypotheses.
      hypotheses_.clear();
      hint_prior_.clear();
      break;
    case HintKind::kResetTo:
      hypotheses_.clear();
      addPoses(hint.poses, 1.0);
      markInjected();
      // The hint is the prior for the next seconds (TrackerConfig::hint_prior_s), and a global
      // run on the next frame checks it: a pose decimetres off can lock onto a wrong local fit.
      hint_prior_.clear();
      for (const TrackedHypothesis& h : hypotheses_) hint_prior_.push_back(h.pose);
      hint_prior_age_s_ = 0.0;
      global_after_hint_ = !hint_prior_.empty();
      break;
    case HintKind::kAdd:
      addPoses(hint.poses, config_.hint_add_share);
      break;
    case HintKind::kOwnHalf:
      // The field is point-symmetric, so a hypothesis in the opponent half and its mirror in the
      // own half explain the observations equally well: keep the mirror, which the prior allows.
      for (TrackedHypothesis& h : hypotheses_) {
        if (h.pose.mean.x > config_.own_half_margin_m) h.pose = mirrored(h.pose);
      }
      for (GaussianPose& p : hint_prior_) {
        if (p.mean.x > config_.own_half_margin_m) p = mirrored(p);
      }
      finishSet();
      break;
    case HintKind::kMirror:
      for (TrackedHypothesis& h : hypotheses_) h.pose = mirrored(h.pose);
      for (GaussianPose& p : hint_prior_) p = mirrored(p);
      break;
  }
}

}  // namespace houghloc
