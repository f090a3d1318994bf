// computeGlobalMetrics(): DESIGN §5.3 `global` section, single-frame hypotheses.
#include <cmath>

#include "tools/offline/evaluation_frames.h"
#include "tools/offline/localization_evaluation.h"

namespace houghloc {

std::optional<GlobalMetrics> computeGlobalMetrics(const OfflineContext& context,
                                                  const std::vector<FrameEstimate>& estimates) {
  if (context.recording.ground_truth.empty()) return std::nullopt;
  GlobalMetrics m;
  int any = 0, top2 = 0, best = 0, all_any = 0, all_best = 0, rank_sum = 0, within = 0;
  long hypotheses = 0;
  std::vector<double> position_errors, heading_errors;
  static const std::vector<GaussianPose> kNone;
  for (const EvaluatedFrame& f : evaluatedFrames(context, estimates)) {
    if (!f.truth) continue;
    ++m.frames_scored;
    const std::vector<GaussianPose>& h = f.estimate ? f.estimate->hypotheses : kNone;
    hypotheses += static_cast<long>(h.size());
    std::vector<Pose2> poses;
    for (const GaussianPose& g : h) poses.push_back(g.mean);
    const CorrectRank correct = correctRankUpToSymmetry(poses, *f.truth);
    const int rank = correct.answer;  // top two and the mean rank count distinct answers
    all_any += rank >= 0;
    all_best += correct.index == 0;
    if (f.view == FrameView::kTwoDirections) {
      ++m.frames_two_directions;
      if (rank >= 0) {
        ++any;
        top2 += rank <= 1;
        best += correct.index == 0;
        rank_sum += rank;
        const PoseError e = symmetricPoseError(poses[static_cast<size_t>(correct.index)], *f.truth);
        position_errors.push_back(e.position_m);
        heading_errors.push_back(e.heading_rad * 180.0 / M_PI);
      }
    }
    if (f.view == FrameView::kParallelOnly) {
      ++m.frames_parallel_only;
      for (const GaussianPose& g : h) {
        if (mahalanobisDistance(g, *f.truth) <= 3.0 ||
            mahalanobisDistance(g, mirrored(*f.truth)) <= 3.0) {
          ++within;
          break;
        }
      }
    }
  }
  m.correct_any_rate = rate(any, m.frames_two_directions);
  m.correct_top2_rate = rate(top2, m.frames_two_directions);
  m.correct_best_rate = rate(best, m.frames_two_directions);
  m.mean_correct_rank = any > 0 ? static_cast<double>(rank_sum) / any : 0.0;
  m.median_position_error_m = median(position_errors);
  m.median_heading_error_deg = median(heading_errors);
  m.parallel_only_within_3sigma = rate(within, m.frames_parallel_only);
  m.all_frames_correct_any_rate = rate(all_any, m.frames_scored);
  m.all_frames_correct_best_rate = rate(all_best, m.frames_scored);
  m.mean_hypotheses = m.frames_scored > 0 ? static_cast<double>(hypotheses) / m.frames_scored : 0.0;
  return m;
}

}  // namespace houghloc
