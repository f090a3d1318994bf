#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/pose2.h"
#include "tools/offline/estimate_csv.h"
#include "tools/offline/offline_context.h"
#include "tools/recording/recording.h"

namespace houghloc {

/// The thresholds of DESIGN §5.3, fixed so that numbers from different runs compare.
constexpr double kCorrectPositionM = 0.10;
constexpr double kCorrectHeadingRad = 3.0 * M_PI / 180.0;
constexpr double kFlipMinDistanceM = 0.5;      ///< a flip is more than this from ground truth
constexpr int kFramesExcludedAfterEvent = 30;  ///< after each KIDNAP and FALL_END
constexpr double kMinDirectionLengthM = 0.5;   ///< visible line length per direction
constexpr double kMinDirectionSeparationDeg = 30.0;
constexpr double kSameDirectionToleranceDeg = 5.0;  ///< segments this close share a direction
constexpr double kMinCircleLengthM = 1.0;           ///< visible centre circle

/// count / total; 0 when total is 0.
inline double rate(int count, int total) {
  return total > 0 ? static_cast<double>(count) / total : 0.0;
}

struct PoseError {
  double position_m = 0.0;
  double heading_rad = 0.0;  ///< absolute, in [0, pi]
};
PoseError poseError(const Pose2& estimate, const Pose2& truth);
bool isCorrect(const Pose2& estimate, const Pose2& truth);
/// Correct against ground truth or its point-symmetric twin (-x, -y, theta + pi).
bool isCorrectUpToSymmetry(const Pose2& estimate, const Pose2& truth);
/// Where the first hypothesis correct up to symmetry stands in a list, best first.
struct CorrectRank {
  int index = -1;  ///< position in the list; -1 when no hypothesis is correct
  /// Rank among distinct answers: a pose and its point-symmetric twin explain a frame equally
  /// well, so a hypothesis correct up to symmetry against an earlier one (its twin or a near
  /// copy) shares that one's rank. Whether a list holds both twins then does not move the truth
  /// out of the top two.
  int answer = -1;
};
CorrectRank correctRankUpToSymmetry(const std::vector<Pose2>& hypotheses, const Pose2& truth);
/// Error against whichever of ground truth and its twin is nearer in position.
PoseError symmetricPoseError(const Pose2& estimate, const Pose2& truth);
/// DESIGN §5.3: closer to the mirrored truth than to the truth and > 0.5 m from the truth.
bool isFlip(const Pose2& estimate, const Pose2& truth);
/// Mahalanobis distance of `truth` from the Gaussian (x, y, theta), theta wrapped; infinity
/// when the covariance is not positive definite.
double mahalanobisDistance(const GaussianPose& hypothesis, const Pose2& truth);

/// What truth/visible.csv says a frame shows (DESIGN §5.3).
enum class FrameView {
  kUnknown,        ///< no truth/visible.csv rows for the frame
  kNoLines,        ///< less than 0.5 m in any direction, little of the circle
  kParallelOnly,   ///< one direction only
  kTwoDirections,  ///< >= 0.5 m in two directions >= 30 deg apart, or >= 1 m of centre circle
};

/// Classifies one frame's truth/visible.csv rows. `field` tells which arcs form the centre circle
/// (full circles centred on the origin); without it every arc counts as the centre circle.
FrameView classifyView(const std::vector<VisibleRecord>& rows, const FieldModel* field);

/// One frame of the evaluated range, with what the run and the recording say about it.
struct EvaluatedFrame {
  int index = 0;  ///< frame index in the recording
  std::int64_t t_us = 0;
  std::optional<Pose2> truth;               ///< groundTruthAt(t_us), +-20 ms
  const FrameEstimate* estimate = nullptr;  ///< none when the run wrote no row for the frame
  FrameView view = FrameView::kUnknown;
  bool excluded = false;  ///< during a fall or within 30 frames after a kidnap or fall end

  const GaussianPose* best() const {
    return estimate && !estimate->hypotheses.empty() ? &estimate->hypotheses.front() : nullptr;
  }
};

/// An event of truth/events.csv placed on the first frame at or after its time.
struct PlacedEvent {
  std::string event;
  std::int64_t t_us = 0;
  int frame = 0;  ///< index into the frames of evaluatedFrames()
};

/// The frames [first_frame, end_frame) of the context's recording matched to `estimates` by t_us,
/// with ground truth, view classes and exclusion windows; `events` (optional) receives the events
/// that fall inside the range.
std::vector<EvaluatedFrame> evaluatedFrames(const OfflineContext& context,
                                            const std::vector<FrameEstimate>& estimates,
                                            std::vector<PlacedEvent>* events = nullptr);

/// Median (mean of the two middle values for an even count) and nearest-rank percentile
/// (sorted[ceil(q n) - 1]); 0 for no values.
double median(std::vector<double> values);
double percentile(std::vector<double> values, double q);

}  // namespace houghloc
