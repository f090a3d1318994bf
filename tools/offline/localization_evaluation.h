#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tools/offline/estimate_csv.h"
#include "tools/offline/offline_context.h"

namespace houghloc {

/// DESIGN §5.3 `global` section: single-frame hypotheses, scored on frames with two directions
/// in view (and, separately, on all scored frames). "Correct" is 0.10 m and 3 deg; every rate
/// here accepts the point-symmetric twin of ground truth. docs/metrics.md defines each key.
/// A rate whose denominator is zero is 0 here and null in JSON.
struct GlobalMetrics {
  int frames_scored = 0;          ///< frames with ground truth
  int frames_two_directions = 0;  ///< of those, with two directions (or the circle) in view
  double correct_any_rate = 0.0;  ///< two-direction frames: a hypothesis correct up to symmetry
  /// Same, among the two best distinct answers (a twin shares its pair's rank, CorrectRank).
  double correct_top2_rate = 0.0;
  double correct_best_rate = 0.0;  ///< same, rank 0
  /// Rank among distinct answers (0 = best) of the first correct hypothesis, where any.
  double mean_correct_rank = 0.0;
  double median_position_error_m = 0.0;  ///< of the first correct hypothesis, m
  double median_heading_error_deg = 0.0;
  double parallel_only_within_3sigma = 0.0;  ///< frames with one direction: truth within 3 sigma
  int frames_parallel_only = 0;
  double all_frames_correct_any_rate = 0.0;   ///< every scored frame, any hypothesis
  double all_frames_correct_best_rate = 0.0;  ///< every scored frame, the best one
  double mean_hypotheses = 0.0;               ///< hypotheses per scored frame
};

/// DESIGN §5.3 `tracking` section: the best hypothesis over time.
struct TrackingMetrics {
  int frames_scored = 0;        ///< frames with ground truth
  int frames_evaluated = 0;     ///< from the first correct pose on, minus falls and 30 frames after
                                ///< kidnaps and fall ends
  int frames_without_pose = 0;  ///< evaluated frames without any hypothesis
  /// Best pose against ground truth over evaluated frames with a pose (m, deg).
  double median_position_error_m = 0.0, p95_position_error_m = 0.0, max_position_error_m = 0.0;
  double median_heading_error_deg = 0.0, p95_heading_error_deg = 0.0, max_heading_error_deg = 0.0;
  /// The same against the nearer of ground truth and its twin.
  double median_position_error_up_to_symmetry_m = 0.0, p95_position_error_up_to_symmetry_m = 0.0;
  double correct_rate = 0.0;  ///< evaluated frames whose best pose is correct
  double correct_up_to_symmetry_rate = 0.0;
  int flips = 0;  ///< evaluated frames whose best pose is a flip (§5.3)
  /// Weight of the best pose's mirror twin over the evaluated frames (poses.csv twin_weight):
  /// how close the run came to flipping; 0 without evaluated frames.
  double twin_weight_max = 0.0, twin_weight_p95 = 0.0;
  int first_correct_frame = -1;  ///< frames from the first frame to the first correct best pose
                                 ///< (-1: never)
  double first_correct_s = -1.0;
  int first_correct_up_to_symmetry_frame = -1;
  /// Per KIDNAP and FALL_END inside the range, in time order: frames from the event's frame to
  /// the first best pose correct up to symmetry (-1: not recovered before the last frame).
  std::vector<int> recovery_frames;
  std::vector<std::string> recovery_events;  ///< KIDNAP or FALL_END, parallel to the above
  std::vector<std::int64_t> recovery_event_t_us;
  int frames_two_directions = 0;
  double two_direction_correct_any_rate = 0.0;   ///< frames with two directions: any hypothesis
                                                 ///< correct up to symmetry
  double two_direction_best_correct_rate = 0.0;  ///< and the best one
  /// Frames per status over the whole range (INITIALIZING, TRACKING, AMBIGUOUS, LOST, then
  /// MISSING for frames without a poses.csv row).
  std::vector<std::pair<std::string, int>> status_counts;
};

nlohmann::json toJson(const GlobalMetrics& metrics);
nlohmann::json toJson(const TrackingMetrics& metrics);

/// Metrics of a run from its estimates and the recording's ground truth, truth/visible.csv and
/// truth/events.csv; none when there is no ground truth. Frames are the recording's frames in
/// [first_frame, end_frame) matched by t_us.
std::optional<GlobalMetrics> computeGlobalMetrics(const OfflineContext& context,
                                                  const std::vector<FrameEstimate>& estimates);
std::optional<TrackingMetrics> computeTrackingMetrics(const OfflineContext& context,
                                                      const std::vector<FrameEstimate>& estimates);

/// What evaluateOutputs() computed and wrote.
struct EvaluationResult {
  std::optional<GlobalMetrics> global;
  std::optional<TrackingMetrics> tracking;
  std::string trajectory_png;  ///< path written (empty when there is no field)
};

/// Reads OUT/poses.csv and OUT/hypotheses.csv, writes the `global` (global_only) or `tracking`
/// section of OUT/metrics.json when there is ground truth, and OUT/trajectory.png. The full and
/// --global-only runs call it after writing their CSV files, and --evaluate-only calls it alone,
/// so both produce identical metrics.json files by construction. Throws RecordingError or
/// std::runtime_error naming the file at fault.
EvaluationResult evaluateOutputs(const OfflineContext& context, bool global_only);

/// Prints the metrics of `result` as the tail of a run's summary table (stdout).
void printEvaluation(const EvaluationResult& result);

}  // namespace houghloc
