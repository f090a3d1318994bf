#pragma once

#include <vector>

#include "field_models/ground_points.h"
#include "localization/global_hough_config.h"

namespace houghloc {

/// Global Hough Localization (Grisetti, Iocchi, Nardi; DESIGN Appendix A): Gaussian pose
/// hypotheses from one frame of ground points and no prior. The map part is computed once in the
/// constructor; locate() is const and keeps no state between frames.
class GlobalHoughLocalizer {
 public:
  explicit GlobalHoughLocalizer(const FieldModel& field, const GlobalHoughConfig& config = {});

  /// Hypotheses best first, weights summing to 1, at most config.hypotheses.max_hypotheses. Empty
  /// when the points carry no line (none, too few, all on one spot); heading-only hypotheses
  /// when lines are seen but no translation fits.
  std::vector<PoseHypothesis> locate(const GroundPoints& frame) const;

  const MapSignature& map() const { return map_; }
  const GlobalHoughConfig& config() const { return config_; }

  // The steps locate() calls in order, public for tests and tools.
  /// Finite points with positive weight within max_range_m, at most max_points.
  WeightedPoints preparePoints(const GroundPoints& frame) const;
  /// False when the points cannot carry a line (too few, all on one spot).
  bool hasLineSupport(const WeightedPoints& points) const;
  /// Step 1: HT_S.
  HoughTransform sensorTransform(const WeightedPoints& points) const;
  /// Step 2: heading candidates theta_R (each with its pi twin).
  std::vector<OrientationCandidate> orientationCandidates(const HoughTransform& sensor) const;
  /// Step 3: constraints per dominant map direction for one heading.
  std::vector<std::vector<TranslationConstraint>> translationConstraints(
      const WeightedPoints& points, double theta_r) const;
  /// Beyond the paper: poses from the centre circle and the penalty marks. With `evidence`, the
  /// rotations about a landmark are ranked with the field edge too (a lone arc of the circle
  /// fits every rotation about its centre; the carpet's edge does not). `folded`: the headings
  /// are one of each twin pair (foldTwins()), and so are the rotations scanned about a circle at
  /// the field's centre.
  std::vector<PoseHypothesis> landmarkPoses(const WeightedPoints& points,
                                            const std::vector<OrientationCandidate>& headings,
                                            const VisibilityEvidence* evidence = nullptr,
                                            bool folded = false) const;
  /// Step 4 scoring: score and inlier share of every candidate against the whole map, minus the
  /// field-edge penalty when `evidence` is given (cheap; the full negative evidence comes with
  /// the refinement).
  void scoreCandidates(std::vector<PoseHypothesis>& candidates, const WeightedPoints& points,
                       const VisibilityEvidence* evidence = nullptr) const;
  /// Step 4 refinement of one survivor (after the coarse iterations of converge()):
  /// Gauss-Newton, observability (kParallel when only parallel lines constrain it; then a scan
  /// along the lines places the mean), covariance, final score including negative evidence.
  /// A kParallel candidate comes back placed on its line (or not at all when the points fit
  /// nowhere along it or none of its positions scores `min_score`, when its line was scanned
  /// before, or when config.max_line_scans lines were scanned in this frame); on the twin of a
  /// line scanned before (a point-symmetric map) it is that scan's hypothesis mirrored, without
  /// a scan. `scans` records the lines placed.
  struct LineScans {
    int count = 0;                      ///< scans so far (at most config.max_line_scans)
    std::vector<PoseHypothesis> lines;  ///< the kParallel candidates placed, one per line
    std::vector<std::vector<PoseHypothesis>> placed;  ///< what each of `lines` gave
  };
  std::vector<PoseHypothesis> refineCandidate(const PoseHypothesis& candidate,
                                              const WeightedPoints& points,
                                              const VisibilityEvidence& evidence, LineScans* scans,
                                              double min_score = -1e300) const;

 private:
  /// What the stages of locate() hand on to each other (global_locate_state.h).
  struct LocateState;

  // The stages of locate(), in the order it runs them.
  /// On a point-symmetric map keeps one heading of each twin pair (LocateState::folded).
  void foldTwins(LocateState& s) const;
  /// Steps 3-4 for one heading: the poses the constraints give, on the carpet, and every 1-D
  /// line candidate (kept for parallel-only frames).
  void addPoseCandidates(double theta_r,
                         const std::vector<std::vector<TranslationConstraint>>& constraints,
                         LocateState& s) const;
  void addLandmarkPoses(LocateState& s) const;
  /// Drops the field edge unless a candidate explains it (see max_best_cost), so that it cannot
  /// shift every score by the same penalty.
  void gateFieldEdge(LocateState& s) const;
  /// The paper's case M = 0: heading-only hypotheses ranked by their Hough support (with their
  /// twins when folded).
  std::vector<PoseHypothesis> headingOnly(LocateState& s) const;
  /// Step 4 scoring, in two rounds: a quarter of the pre-score points ranks all candidates, the
  /// best few times `keep` are scored with all pre-score points, then pruned by segment extents.
  void scoreAndPrune(LocateState& s) const;
  /// Its first round: keeps the `kept` best of many candidates (by positive score
  /// on prescore_points / 4 points less the field-edge penalty), best first.
  void keepBestOfFirstRound(std::vector<PoseHypothesis>& located, std::size_t kept,
                            LocateState& s) const;
  /// Coarse Gauss-Newton of every pruned candidate on the pre-score points; keeps one of each
  /// group that converged to the same pose (or, folded, to its twin), best score first.
  void converge(LocateState& s) const;
  /// refineCandidate() of every survivor, on the refinement points, and when folded the mirror
  /// of what it gives; a survivor placed by a scan along its line must reach competingScore()
  /// of the best hypothesis refined before it.
  void refineSurvivors(LocateState& s) const;
  /// Merges duplicates, full poses and 1-D hypotheses apart: a full pose near a 1-D hypothesis'
  /// mean is not its duplicate (it says where along the line, which the 1-D one does not).
  void mergeRefined(LocateState& s) const;
  /// Parallel-only frames: everyLineHypotheses() joined to the merged hypotheses; a new 1-D
  /// hypothesis replaces a weaker one on the same line.
  void addEveryLine(LocateState& s) const;
  /// At most config.max_hypotheses, sorted, weights normalised. On a point-symmetric map a pose
  /// and its twin (-x, -y, theta + pi) explain every frame equally well: with more distinct
  /// hypotheses than slots, each pair is represented once (best first) before twins fill the
  /// slots that are left.
  std::vector<PoseHypothesis> selectHypotheses(LocateState& s) const;

  // Parts of the stages.
  /// The candidate's line scanned and the 1-D hypothesis placed on it; none when the line has
  /// no place where the points fit, or when no scanned position's score (positive less negative
  /// evidence) reaches `min_score`.
  std::vector<PoseHypothesis> placeAlongLines(const PoseHypothesis& candidate,
                                              const WeightedPoints& points,
                                              const VisibilityEvidence& evidence,
                                              double min_score = -1e300) const;
  /// Of a scan along the lines: the best score (positive less negative evidence) and the first
  /// and last positions (indices) whose score is within line_scan_tolerance of it.
  struct AlongLineFit {
    bool found = false;
    double best = -1e300;
    std::size_t best_index = 0;  ///< the first position with the best score
    std::size_t first = 0, last = 0;
  };
  /// The positions scanned along candidate's line_direction (s, m from its translation) and
  /// their fit.
  struct AlongLineScan {
    std::vector<double> s_values;
    AlongLineFit fit;
  };
  /// The scan over [s_min, s_max] in line_scan_step_m steps, coarse to fine: every other
  /// position, then the ones between next to the best and at the ends of the span where the
  /// points fit. `few`: the points subsampled for scoring. Stops after the coarse positions
  /// (fit not found) when none has a score of `min_score`.
  AlongLineScan scanAlongLine(const PoseHypothesis& candidate, const WeightedPoints& few,
                              const VisibilityEvidence& evidence, double s_min, double s_max,
                              double min_score) const;
  /// The fit of the scan at s_values along candidate's line_direction from its translation, with
  /// `positive` the positive score at each position; the negative evidence only where needed.
  /// `upper` holds an upper bound of each position's score (at first `positive`), or the score
  /// where `exact`; the fit tightens them, and a later fit over some of the same positions can
  /// start from them. Not found when no position's score reaches `min_score` (the negative
  /// evidence is then computed only where a position could).
  AlongLineFit fitAlongLine(const PoseHypothesis& candidate, const std::vector<double>& s_values,
                            const std::vector<double>& positive, const VisibilityEvidence& evidence,
                            std::vector<double>* upper, std::vector<char>* exact,
                            double min_score = -1e300) const;
  /// True when only parallel lines are in view: a 1-D hypothesis explains the points at least
  /// parallel_only_share as well as the best full pose, and that pose has few points across the
  /// lines.
  bool parallelOnlyFrame(const std::vector<PoseHypothesis>& refined,
                         const WeightedPoints& points) const;
  /// Parallel-only frames: every 1-D line candidate (all map lines of the seen direction, every
  /// heading) placed along its line by the scan; one of each pair of point-symmetric twins is
  /// scanned and the other mirrored. A line whose scan stays below the pruning share
  /// (min_relative_score) of `best_score` is left out, as pruning leaves out such a candidate,
  /// and so is a line of `placed` (a survivor's, already among the hypotheses).
  std::vector<PoseHypothesis> everyLineHypotheses(const std::vector<PoseHypothesis>& lines,
                                                  const std::vector<PoseHypothesis>& placed,
                                                  const WeightedPoints& points,
                                                  const VisibilityEvidence& evidence,
                                                  double best_score) const;
  /// The least score (min_relative_score of `best`, the best hypothesis' score so far) a
  /// hypothesis needs to compete: below it pruning would drop it as a candidate, and its weight
  /// would be at most exp(-10) of the best's at the default temperature. A scan along lines
  /// looks only for positions that reach it.
  double competingScore(double best) const;
  /// True when `line` (a kParallel candidate) lies on a line of `scanned`, or on a twin of one
  /// when `mirrors` (a point-symmetric map): same heading, same offset across the lines.
  bool lineScanned(const std::vector<PoseHypothesis>& scanned, const PoseHypothesis& line,
                   bool mirrors) const;
  /// On a point-symmetric map, the index in `scanned` of the line whose twin `line` lies on (its
  /// scan's hypothesis mirrored is what a scan of `line` would give); -1 when none.
  int scannedTwin(const std::vector<PoseHypothesis>& scanned, const PoseHypothesis& line) const;
  /// The index of the first line of `scanned` that `pose` lies on; -1 when none.
  static int scannedLineIndex(const std::vector<PoseHypothesis>& scanned, const Pose2& pose);
  /// Whether `pose` lies on the line of `scanned` (a kParallel candidate): same heading, same
  /// offset across the lines.
  static bool onScannedLine(const PoseHypothesis& scanned, const Pose2& pose);
  void finish(PoseHypothesis& candidate, const WeightedPoints& points,
              const VisibilityEvidence& evidence) const;
  bool onCarpet(const Pose2& pose) const;
  /// The hypothesis-set config without a cap on the number (for merging).
  HypothesisSetConfig uncapped() const;
  /// Headings (best local maxima of the score) for rotations of the view about a landmark seen
  /// at p_robot and mapped to p_field. `half_turn`: the score repeats after half a turn (the
  /// twins of a point-symmetric map about its centre), so only half a turn is scanned.
  std::vector<OrientationCandidate> scanHeadings(const Eigen::Vector2d& p_robot,
                                                 const Eigen::Vector2d& p_field,
                                                 const WeightedPoints& points,
                                                 const VisibilityEvidence* evidence,
                                                 bool half_turn = false) const;

  GlobalHoughConfig config_;
  MapSignature map_;
};

}  // namespace houghloc
