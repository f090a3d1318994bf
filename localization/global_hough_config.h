#pragma once

#include <cstddef>

#include "localization/hypothesis_set.h"
#include "localization/landmarks.h"
#include "localization/map_signature.h"
#include "localization/negative_evidence.h"
#include "localization/orientation_search.h"
#include "localization/pose_refinement.h"
#include "localization/pose_scoring.h"
#include "localization/pose_solver.h"
#include "localization/translation_search.h"

namespace houghloc {

/// Everything GlobalHoughLocalizer can be tuned with (YAML section `global:`, DESIGN §2).
struct GlobalHoughConfig {
  double max_range_m = 8.0;           ///< points farther than this are dropped
  std::size_t max_points = 500;       ///< larger inputs are subsampled evenly
  std::size_t prescore_points = 80;   ///< points used to pre-score the raw candidates
  std::size_t refine_points = 160;    ///< points used by the final refinement and score (even
                                      ///< subsample; more add time, not accuracy)
  std::size_t min_points = 6;         ///< fewer points: no hypothesis
  double min_spread_m = 0.1;          ///< std dev along the points' main axis, else none
  double min_observed_weight = 4.0;   ///< point weight on lines across a direction for it to
                                      ///< count as observed (else the pose is kParallel)
  double line_scan_step_m = 0.1;      ///< step of the scan along parallel lines
  double line_scan_tolerance = 0.2;   ///< positions within this share of the best score are
                                      ///< equally likely along the lines
  int max_line_scans = 12;            ///< parallel-only candidates scanned per frame
  double parallel_floor_m = 0.03;     ///< added across the lines to a 1-D hypothesis' std dev:
                                      ///< its heading error moves the line along its length
  double parallel_floor_rad = 0.015;  ///< same for the heading
  double parallel_only_share = 0.9;   ///< a 1-D hypothesis scoring at least this share of the
                                      ///< best one marks a parallel-only frame: every map line
                                      ///< of the seen direction is then tried (unitless)
  bool use_circle = true;             ///< beyond the paper: centre-circle candidates
  bool use_marks = true;              ///< beyond the paper: penalty-mark candidates

  MapSignatureConfig map;
  OrientationConfig orientation;
  TranslationConfig translation;
  PoseSolverConfig solver;
  ScoringConfig scoring;
  PruningConfig pruning;
  RefinementConfig refinement;
  NegativeEvidenceConfig negative;
  LandmarkConfig landmarks;
  HypothesisSetConfig hypotheses;
};

}  // namespace houghloc
