#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_models/field_model.h"
#include "field_models/ground_points.h"
#include "field_models/pose2.h"

namespace houghloc {

/// Beyond the paper: where the cameras saw the carpet end (GroundPoints::field_edge), at any
/// range. The lines alone leave some views ambiguous that the carpet's edge settles: a lone arc
/// of the MSL centre circle fits every rotation about its centre, but the edge lies 7 m away
/// towards a touch line and 11 m towards a goal line.
struct FieldEdgeConfig {
  bool enabled = true;
  double weight_m = 2.0;        ///< penalty, in metres of seen line, of a pose that every edge
                                ///< sample contradicts (the mean of the samples' costs counts)
  double sigma_floor_m = 0.15;  ///< added in quadrature to each sample's range sigma: the edge
                                ///< is not a perfect line and the camera height is a bit off
  double clip_sigmas = 3.0;     ///< a sample's cost saturates at this many sigmas, so a few
                                ///< wrong columns cannot dominate
  double nearer_weight = 0.5;   ///< share of the cost when the edge is seen nearer than the
                                ///< pose predicts: something may stand on the field in front
  double max_range_m = 30.0;    ///< samples farther away are ignored (and non-finite ones)
  int min_samples = 4;          ///< fewer samples say too little to count
  double max_best_cost = 0.35;  ///< when no candidate pose of a frame has a mean cost below this,
                                ///< the samples are not the carpet's edge (a robot right in
                                ///< front, a wrong boundary) and the frame ignores them; a clean
                                ///< edge costs about 0.11 at the truth
};

/// The per-frame field-edge samples, ready to be compared with a pose's predicted carpet edge.
class FieldEdgeEvidence {
 public:
  FieldEdgeEvidence() = default;
  FieldEdgeEvidence(const GroundPoints& frame, const FieldEdgeConfig& config);

  bool empty() const { return range_.empty(); }
  double maxBestCost() const { return config_.max_best_cost; }
  void clear();
  /// Mean cost per sample in [0, 1]: 0 when every sample lies where the pose puts the carpet's
  /// edge (carpet = |x| <= half_length, |y| <= half_width, field frame), 1 when every one is
  /// clip_sigmas or more away.
  double meanCost(const Pose2& field_T_robot, double half_length, double half_width) const;
  /// weight_m * meanCost: the penalty in metres of line.
  double penaltyMetres(const Pose2& field_T_robot, double half_length, double half_width) const;

 private:
  FieldEdgeConfig config_;
  // The samples, one array per quantity so that the per-sample costs form a loop the compiler
  // vectorises (meanCost runs for every candidate pose of a frame).
  std::vector<double> direction_x_, direction_y_;  ///< unit, robot frame
  std::vector<double> range_;
  std::vector<double> inv_sigma_;  ///< 1 / (clip_sigmas * total sigma)
};

}  // namespace houghloc
