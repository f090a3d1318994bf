// computeTrackingMetrics(): DESIGN §5.3 `tracking` section, the best pose over time.
#include <algorithm>
#include <cmath>
#include <map>

#include "tools/offline/evaluation_frames.h"
#include "tools/offline/localization_evaluation.h"

namespace houghloc {
namespace {

double degrees(double rad) { return rad * 180.0 / M_PI; }

bool bestCorrect(const EvaluatedFrame& f) {
  return f.truth && f.best() && isCorrect(f.best()->mean, *f.truth);
}
bool bestCorrectUpToSymmetry(const EvaluatedFrame& f) {
  return f.truth && f.best() && isCorrectUpToSymmetry(f.best()->mean, *f.truth);
}

std::vector<std::pair<std::string, int>> statusCounts(const std::vector<EvaluatedFrame>& frames) {
  std::map<std::string, int> counts;
  for (const EvaluatedFrame& f : frames) ++counts[f.estimate ? f.estimate->status : "MISSING"];
  std::vector<std::pair<std::string, int>> out;
  for (const char* s : {"INITIALIZING", "TRACKING", "AMBIGUOUS", "LOST", "MISSING"}) {
    out.emplace_back(s, counts.count(s) ? counts[s] : 0);
    counts.erase(s);
  }
  for (const auto& [status, n] : counts) out.emplace_back(status, n);  // none from the reader
  return out;
}

void addRecoveries(const std::vector<EvaluatedFrame>& frames,
                   const std::vector<PlacedEvent>& events, TrackingMetrics* m) {
  for (const PlacedEvent& e : events) {
    if (e.event != "KIDNAP" && e.event != "FALL_END") continue;
    int frames_to_recover = -1;
    for (size_t i = static_cast<size_t>(e.frame); i < frames.size(); ++i) {
      if (bestCorrectUpToSymmetry(frames[i])) {
        frames_to_recover = static_cast<int>(i) - e.frame;
        break;
      }
    }
    m->recovery_frames.push_back(frames_to_recover);
    m->recovery_events.push_back(e.event);
    m->recovery_event_t_us.push_back(e.t_us);
  }
}

}  // namespace

std::optional<TrackingMetrics> computeTrackingMetrics(const OfflineContext& context,
                                                      const std::vector<FrameEstimate>& estimates) {
  if (context.recording.ground_truth.empty()) return std::nullopt;
  std::vector<PlacedEvent> events;
  const std::vector<EvaluatedFrame> frames = evaluatedFrames(context, estimates, &events);
  TrackingMetrics m;
  m.status_counts = statusCounts(frames);
  int two_any = 0, two_best = 0;
  for (size_t i = 0; i < frames.size(); ++i) {
    const EvaluatedFrame& f = frames[i];
    if (!f.truth) continue;
    ++m.frames_scored;
    const int index = static_cast<int>(i);
    if (m.first_correct_frame < 0 && bestCorrect(f)) {
      m.first_correct_frame = index;
      m.first_correct_s = 1e-6 * static_cast<double>(f.t_us - frames.front().t_us);
    }
    if (m.first_correct_up_to_symmetry_frame < 0 && bestCorrectUpToSymmetry(f)) {
      m.first_correct_up_to_symmetry_frame = index;
    }
    if (f.view == FrameView::kTwoDirections) {
      ++m.frames_two_directions;
      const std::vector<GaussianPose> none;
      const auto& h = f.estimate ? f.estimate->hypotheses : none;
      two_any += std::any_of(h.begin(), h.end(), [&](const GaussianPose& g) {
        return isCorrectUpToSymmetry(g.mean, *f.truth);
      });
      two_best += bestCorrectUpToSymmetry(f);
    }
  }

  std::vector<double> position, heading, position_sym, twin;
  int correct = 0, correct_sym = 0;
  for (size_t i = m.first_correct_frame < 0 ? frames.size() : m.first_correct_frame;
       i < frames.size(); ++i) {
    const EvaluatedFrame& f = frames[i];
    if (!f.truth || f.excluded) continue;
    ++m.frames_evaluated;
    if (!f.best()) {
      ++m.frames_without_pose;
      continue;
    }
    const Pose2& best = f.best()->mean;
    twin.push_back(f.estimate->twinWeight());
    const PoseError e = poseError(best, *f.truth);
    position.push_back(e.position_m);
    heading.push_back(degrees(e.heading_rad));
    position_sym.push_back(symmetricPoseError(best, *f.truth).position_m);
    correct += isCorrect(best, *f.truth);
    correct_sym += isCorrectUpToSymmetry(best, *f.truth);
    m.flips += isFlip(best, *f.truth);
  }
  m.median_position_error_m = median(position);
  m.p95_position_error_m = percentile(position, 0.95);
  m.max_position_error_m =
      position.empty() ? 0.0 : *std::max_element(position.begin(), position.end());
  m.twin_weight_max = twin.empty() ? 0.0 : *std::max_element(twin.begin(), twin.end());
  m.twin_weight_p95 = percentile(twin, 0.95);
  m.median_heading_error_deg = median(heading);
  m.p95_heading_error_deg = percentile(heading, 0.95);
  m.max_heading_error_deg =
      heading.empty() ? 0.0 : *std::max_element(heading.begin(), heading.end());
  m.median_position_error_up_to_symmetry_m = median(position_sym);
  m.p95_position_error_up_to_symmetry_m = percentile(position_sym, 0.95);
  m.correct_rate = rate(correct, m.frames_evaluated);
  m.correct_up_to_symmetry_rate = rate(correct_sym, m.frames_evaluated);
  m.two_direction_correct_any_rate = rate(two_any, m.frames_two_directions);
  m.two_direction_best_correct_rate = rate(two_best, m.frames_two_directions);
  addRecoveries(frames, events, &m);
  return m;
}

}  // namespace houghloc
