// toJson(), evaluateOutputs() and printEvaluation(); the metrics themselves are in
// global_metrics.cc and tracking_metrics.cc.
#include "tools/offline/localization_evaluation.h"

#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "tools/offline/evaluation_frames.h"
#include "tools/offline/offline_output.h"
#include "tools/offline/trajectory_plot.h"

namespace houghloc {
namespace {

/// A value that only means something when `defined` (a rate over zero frames is null).
nlohmann::json orNull(double value, bool defined) {
  return defined ? nlohmann::json(value) : nlohmann::json(nullptr);
}
nlohmann::json orNull(int value, bool defined) {
  return defined ? nlohmann::json(value) : nlohmann::json(nullptr);
}

void addThresholds(nlohmann::json* j) {
  (*j)["correct_position_m"] = kCorrectPositionM;
  (*j)["correct_heading_deg"] = kCorrectHeadingRad * 180.0 / M_PI;
}

std::string percent(double rate, bool defined) {
  if (!defined) return "n/a";
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f %%", 100.0 * rate);
  return text;
}

void printGlobal(const GlobalMetrics& m) {
  const bool two = m.frames_two_directions > 0;
  const bool found = two && m.correct_any_rate > 0.0;
  std::printf("Global localization (single frames; correct = 0.10 m and 3 deg, up to symmetry)\n");
  std::printf("  two directions   %d of %d scored frames: any %s, top two %s, best %s\n",
              m.frames_two_directions, m.frames_scored, percent(m.correct_any_rate, two).c_str(),
              percent(m.correct_top2_rate, two).c_str(), percent(m.correct_best_rate, two).c_str());
  if (found) {
    std::printf("  correct one      mean rank %.2f, median error %.3f m %.2f deg\n",
                m.mean_correct_rank, m.median_position_error_m, m.median_heading_error_deg);
  }
  std::printf("  parallel only    %d frames: truth within 3 sigma %s\n", m.frames_parallel_only,
              percent(m.parallel_only_within_3sigma, m.frames_parallel_only > 0).c_str());
  std::printf("  all frames       any %s, best %s, %.1f hypotheses per frame\n",
              percent(m.all_frames_correct_any_rate, m.frames_scored > 0).c_str(),
              percent(m.all_frames_correct_best_rate, m.frames_scored > 0).c_str(),
              m.mean_hypotheses);
}

void printTracking(const TrackingMetrics& m) {
  const bool evaluated = m.frames_evaluated > 0;
  const bool errors = m.frames_evaluated > m.frames_without_pose;
  std::printf("Tracking (best pose; correct = 0.10 m and 3 deg)\n");
  std::printf(
      "  frames           %d scored, %d evaluated (from the first correct pose, without "
      "falls and 30 frames after kidnaps and fall ends), %d without a pose\n",
      m.frames_scored, m.frames_evaluated, m.frames_without_pose);
  if (errors) {
    std::printf(
        "  error            median %.3f m %.2f deg | p95 %.3f m %.2f deg | max %.3f m "
        "%.2f deg\n",
        m.median_position_error_m, m.median_heading_error_deg, m.p95_position_error_m,
        m.p95_heading_error_deg, m.max_position_error_m, m.max_heading_error_deg);
  }
  std::printf(
      "  correct          %s (up to symmetry %s), flipped frames %d, twin weight max %.3f "
      "p95 %.3f\n",
      percent(m.correct_rate, evaluated).c_str(),
      percent(m.correct_up_to_symmetry_rate, evaluated).c_str(), m.flips, m.twin_weight_max,
      m.twin_weight_p95);
  if (m.first_correct_frame >= 0) {
    std::printf("  first correct    frame %d (%.2f s)\n", m.first_correct_frame, m.first_correct_s);
  } else {
    std::printf("  first correct    never (up to symmetry: %s)\n",
                m.first_correct_up_to_symmetry_frame >= 0
                    ? ("frame " + std::to_string(m.first_correct_up_to_symmetry_frame)).c_str()
                    : "never");
  }
  for (size_t i = 0; i < m.recovery_frames.size(); ++i) {
    const int n = m.recovery_frames[i];
    std::printf("  recovery         %s at %.2f s: %s\n", m.recovery_events[i].c_str(),
                1e-6 * static_cast<double>(m.recovery_event_t_us[i]),
                n >= 0 ? (std::to_string(n) + " frames").c_str() : "not recovered");
  }
  std::printf("  two directions   %d frames: a hypothesis correct up to symmetry %s, the best %s\n",
              m.frames_two_directions,
              percent(m.two_direction_correct_any_rate, m.frames_two_directions > 0).c_str(),
              percent(m.two_direction_best_correct_rate, m.frames_two_directions > 0).c_str());
  std::printf("  status          ");
  for (const auto& [status, count] : m.status_counts) {
    if (count > 0) std::printf(" %s %d", status.c_str(), count);
  }
  std::printf("\n");
}

std::string format(const char* pattern, double a, double b = 0.0) {
  char text[96];
  std::snprintf(text, sizeof(text), pattern, a, b);
  return text;
}

/// A few lines of metrics for the plot's legend panel, so the picture tells how the run went.
std::vector<std::string> plotNotes(const EvaluationResult& r) {
  std::vector<std::string> notes;
  if (const auto& g = r.global; g && g->frames_two_directions > 0) {
    notes.push_back("Two-direction frames: " + std::to_string(g->frames_two_directions));
    notes.push_back(format("correct (sym.) any %.1f %%", 100.0 * g->correct_any_rate));
    notes.push_back(format("top two %.1f %%, best %.1f %%", 100.0 * g->correct_top2_rate,
                           100.0 * g->correct_best_rate));
  }
  if (const auto& t = r.tracking; t && t->frames_evaluated > 0) {
    notes.push_back("Evaluated frames: " + std::to_string(t->frames_evaluated));
    notes.push_back(format("correct %.1f %% (sym. %.1f %%)", 100.0 * t->correct_rate,
                           100.0 * t->correct_up_to_symmetry_rate));
    if (t->frames_evaluated > t->frames_without_pose) {
      notes.push_back(format("median error %.1f cm %.1f deg", 100.0 * t->median_position_error_m,
                             t->median_heading_error_deg));
    }
    notes.push_back("flipped frames " + std::to_string(t->flips));
    notes.push_back(
        format("twin weight max %.3f, p95 %.3f", t->twin_weight_max, t->twin_weight_p95));
    for (size_t i = 0; i < t->recovery_frames.size(); ++i) {
      const int n = t->recovery_frames[i];
      notes.push_back((t->recovery_events[i] == "KIDNAP" ? "kidnap: " : "fall: ") +
                      (n >= 0 ? "recovered in " + std::to_string(n) + " frames" : "not recovered"));
    }
  }
  return notes;
}

}  // namespace

nlohmann::json toJson(const GlobalMetrics& m) {
  const bool two = m.frames_two_directions > 0;
  const bool found = two && m.correct_any_rate > 0.0;
  nlohmann::json j;
  addThresholds(&j);
  j["frames_scored"] = m.frames_scored;
  j["frames_two_directions"] = m.frames_two_directions;
  j["correct_any_rate"] = orNull(m.correct_any_rate, two);
  j["correct_top2_rate"] = orNull(m.correct_top2_rate, two);
  j["correct_best_rate"] = orNull(m.correct_best_rate, two);
  j["mean_correct_rank"] = orNull(m.mean_correct_rank, found);
  j["median_position_error_m"] = orNull(m.median_position_error_m, found);
  j["median_heading_error_deg"] = orNull(m.median_heading_error_deg, found);
  j["frames_parallel_only"] = m.frames_parallel_only;
  j["parallel_only_within_3sigma"] =
      orNull(m.parallel_only_within_3sigma, m.frames_parallel_only > 0);
  j["all_frames_correct_any_rate"] = orNull(m.all_frames_correct_any_rate, m.frames_scored > 0);
  j["all_frames_correct_best_rate"] = orNull(m.all_frames_correct_best_rate, m.frames_scored > 0);
  j["mean_hypotheses"] = m.mean_hypotheses;
  return j;
}

nlohmann::json toJson(const TrackingMetrics& m) {
  const bool evaluated = m.frames_evaluated > 0;
  const bool errors = m.frames_evaluated > m.frames_without_pose;
  const bool two = m.frames_two_directions > 0;
  nlohmann::json j;
  addThresholds(&j);
  j["frames_scored"] = m.frames_scored;
  j["frames_evaluated"] = m.frames_evaluated;
  j["frames_without_pose"] = m.frames_without_pose;
  j["median_position_error_m"] = orNull(m.median_position_error_m, errors);
  j["p95_position_error_m"] = orNull(m.p95_position_error_m, errors);
  j["max_position_error_m"] = orNull(m.max_position_error_m, errors);
  j["median_heading_error_deg"] = orNull(m.median_heading_error_deg, errors);
  j["p95_heading_error_deg"] = orNull(m.p95_heading_error_deg, errors);
  j["max_heading_error_deg"] = orNull(m.max_heading_error_deg, errors);
  j["median_position_error_up_to_symmetry_m"] =
      orNull(m.median_position_error_up_to_symmetry_m, errors);
  j["p95_position_error_up_to_symmetry_m"] = orNull(m.p95_position_error_up_to_symmetry_m, errors);
  j["correct_rate"] = orNull(m.correct_rate, evaluated);
  j["correct_up_to_symmetry_rate"] = orNull(m.correct_up_to_symmetry_rate, evaluated);
  j["flips"] = m.flips;
  j["twin_weight_max"] = orNull(m.twin_weight_max, evaluated);
  j["twin_weight_p95"] = orNull(m.twin_weight_p95, evaluated);
  j["first_correct_frame"] = orNull(m.first_correct_frame, m.first_correct_frame >= 0);
  j["first_correct_s"] = orNull(m.first_correct_s, m.first_correct_frame >= 0);
  j["first_correct_up_to_symmetry_frame"] =
      orNull(m.first_correct_up_to_symmetry_frame, m.first_correct_up_to_symmetry_frame >= 0);
  nlohmann::json recoveries = nlohmann::json::array();
  for (size_t i = 0; i < m.recovery_frames.size(); ++i) {
    recoveries.push_back({{"event", m.recovery_events[i]},
                          {"t_us", m.recovery_event_t_us[i]},
                          {"frames", orNull(m.recovery_frames[i], m.recovery_frames[i] >= 0)}});
  }
  j["recovery"] = recoveries;
  j["frames_two_directions"] = m.frames_two_directions;
  j["two_direction_correct_any_rate"] = orNull(m.two_direction_correct_any_rate, two);
  j["two_direction_best_correct_rate"] = orNull(m.two_direction_best_correct_rate, two);
  nlohmann::json status = nlohmann::json::object();
  for (const auto& [name, count] : m.status_counts) status[name] = count;
  j["status_counts"] = status;
  return j;
}

EvaluationResult evaluateOutputs(const OfflineContext& context, bool global_only) {
  const std::vector<FrameEstimate> estimates = readFrameEstimates(context.out_dir);
  EvaluationResult result;
  if (global_only) {
    result.global = computeGlobalMetrics(context, estimates);
    if (result.global) writeMetricsSection(context.out_dir, "global", toJson(*result.global));
  } else {
    result.tracking = computeTrackingMetrics(context, estimates);
    if (result.tracking) writeMetricsSection(context.out_dir, "tracking", toJson(*result.tracking));
  }
  if (context.field) {
    const std::string path = (std::filesystem::path(context.out_dir) / "trajectory.png").string();
    const cv::Mat plot = drawTrajectoryPlot(context, estimates, plotNotes(result));
    bool written = false;
    try {
      written = cv::imwrite(path, plot);
    } catch (const cv::Exception&) {
      written = false;
    }
    if (!written) throw std::runtime_error(path + ": cannot write");
    result.trajectory_png = path;
  }
  return result;
}

void printEvaluation(const EvaluationResult& result) {
  if (!result.global && !result.tracking) {
    std::printf("No ground truth (groundtruth.csv): localization metrics not computed\n");
  }
  if (result.global) printGlobal(*result.global);
  if (result.tracking) printTracking(*result.tracking);
  if (!result.trajectory_png.empty()) {
    std::printf("  trajectory plot  %s\n", result.trajectory_png.c_str());
  }
}

}  // namespace houghloc
