#pragma once

#include <vector>

#include "field_models/distance_grid.h"
#include "field_models/field_model.h"
#include "field_models/ground_points.h"
#include "localization/pose_scoring.h"

namespace houghloc {

/// The exhaustive reference for global localization (issue 6): every pose on a coarse lattice
/// over the carpet is scored, the best coarse optima are refined locally, and the best distinct
/// optima are returned. Positive evidence only, with the localizer's distance grid and kernel.
struct GridSearchConfig {
  double step_m = 0.10;                  ///< coarse lattice spacing of x and y
  double step_rad = 5.0 * M_PI / 180.0;  ///< coarse heading spacing
  std::size_t coarse_points = 150;       ///< points scored in the coarse stage (even subsample)
  std::size_t fine_points = 600;         ///< points scored in the refinement
  double max_range_m = 8.0;              ///< points farther than this are dropped
  int starts = 40;                       ///< distinct coarse optima refined
  int max_optima = 12;                   ///< distinct optima returned
  double distinct_m = 0.25;              ///< optima closer than this ...
  double distinct_rad = 0.1;             ///< ... and this in heading are the same optimum
  /// Coarse kernel width: the fine width plus the lattice's worst misplacement of a point at
  /// range r (half a cell diagonal, rounding to cells, r * half the heading step).
  double coarse_extra_m = 0.12;
  ScoringConfig scoring;    ///< fine scoring, same as the localizer's
  DistanceGridConfig grid;  ///< same as the localizer's (MapSignatureConfig::grid)
};

struct GridSearchOptimum {
  Pose2 field_T_robot;
  double score = 0.0;  ///< scorePose() with config.scoring
};

class GridSearchLocalizer {
 public:
  explicit GridSearchLocalizer(const FieldModel& field, const GridSearchConfig& config = {});

  /// Up to max_optima distinct optima, best first.
  std::vector<GridSearchOptimum> locate(const GroundPoints& frame) const;
  const DistanceGrid& grid() const { return grid_; }

 private:
  struct Start {
    Pose2 pose;
    double score;
  };
  std::vector<Start> coarseSearch(const WeightedPoints& points) const;
  GridSearchOptimum refine(const WeightedPoints& points, const Pose2& start) const;

  FieldModel field_;
  GridSearchConfig config_;
  DistanceGrid grid_;
  // Coarse lattice of distances (step_m cells) covering the carpet plus the largest range.
  Eigen::Vector2d lattice_origin_ = Eigen::Vector2d::Zero();
  int lattice_cols_ = 0, lattice_rows_ = 0;
  std::vector<float> lattice_distance_;
};

}  // namespace houghloc
