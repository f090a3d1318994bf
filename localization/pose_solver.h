#pragma once

#include <Eigen/Core>
#include <vector>

#include "localization/pose_hypothesis.h"
#include "localization/translation_search.h"

namespace houghloc {

struct PoseSolverConfig {
  double sigma_rho_m = 0.03;              ///< std dev of one constraint d (about the rho bin)
  double sigma_theta_rad = 0.02;          ///< heading std dev from step 2 (about a column)
  double sigma_along_m = 3.0;             ///< std dev along the lines of a parallel-only pose
  double sigma_unknown_m = 10.0;          ///< position std dev of a heading-only hypothesis
  double min_direction_angle_rad = 0.35;  ///< constraints closer in angle count as parallel
  int max_pairs = 144;                    ///< constraint pairs combined per heading
  double dominance_ratio = 3.0;  ///< a direction this much stronger than every other one also
                                 ///< yields parallel-only (1-D) candidates
};

/// Least squares of the constraints A T = d with rows (cos theta_mu, sin theta_mu); covariance
/// sigma_rho^2 (A^T A)^-1 (Appendix A step 4). False when A^T A is singular (parallel only).
bool solveTranslation(const std::vector<TranslationConstraint>& constraints, double sigma_rho_m,
                      Eigen::Vector2d* translation, Eigen::Matrix2d* covariance);

/// Step 4 for one heading candidate theta_R: every combination of one shift per non-parallel
/// direction pair gives a full pose; a single direction gives 1-D hypotheses (the paper's case
/// M = 1, centred on the line's closest point to the field origin), and so does a direction
/// that dominates the others (their peaks may be spurious); none gives heading only.
std::vector<PoseHypothesis> solvePoses(
    double theta_r, const std::vector<std::vector<TranslationConstraint>>& per_direction,
    const PoseSolverConfig& config);

/// The paper's M = 1 Gaussian: position d n + s u, covariance sigma_rho^2 n n^T + sigma_along^2
/// u u^T (n = normal of the lines, u along them).
PoseHypothesis parallelHypothesis(double theta_r, const TranslationConstraint& constraint,
                                  double along_m, const PoseSolverConfig& config);

/// Parallel-only frames: one 1-D hypothesis per shift of the direction with the most support
/// for heading theta_R (each shift aligns the seen line with one map line of that direction), so
/// that every map line of the direction is tried. Empty when no direction has a constraint.
std::vector<PoseHypothesis> lineCandidates(
    double theta_r, const std::vector<std::vector<TranslationConstraint>>& per_direction,
    const PoseSolverConfig& config);

/// The paper's M = 0 case: heading theta_R, position unknown (at the field origin).
PoseHypothesis headingOnlyHypothesis(double theta_r, const PoseSolverConfig& config);

}  // namespace houghloc
