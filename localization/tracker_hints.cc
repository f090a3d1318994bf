// HypothesisTracker::applyHint: DESIGN §7 hints, kept apart from the filter itself.
#include "localization/hypothesis_tracker.h"

namespace houghloc {

void HypothesisTracker::applyHint(const LocalizationHint& hint) {
  switch (hint.kind) {
    case HintKind::kUnknown:
      // Nothing we hold can be trusted: start over from global hypotheses.
      hypotheses_.clear();
      break;
    case HintKind::kResetTo:
      hypotheses_.clear();
      addPoses(hint.poses, 1.0);
      markInjected();
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
      finishSet();
      break;
    case HintKind::kMirror:
      for (TrackedHypothesis& h : hypotheses_) h.pose = mirrored(h.pose);
      break;
  }
}

}  // namespace houghloc
