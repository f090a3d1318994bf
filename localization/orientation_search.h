#pragma once

#include <vector>

namespace houghloc {

struct OrientationConfig {
  double min_correlation = 0.05;  ///< candidates need c(phi) above this (profiles unit norm)
  double relative_share = 0.25;   ///< ... and above this share of the best c(phi)
  int max_candidates = 3;         ///< maxima kept in [0, pi); each also yields its pi twin
  double suppression_rad = 0.07;  ///< non-maximum suppression window around a kept maximum
};

/// A heading candidate theta_R (robot heading in the field, rad) and its correlation value.
struct OrientationCandidate {
  double theta_rad = 0.0;
  double correlation = 0.0;
};

/// c(phi_k) = sum_theta h(theta) m(theta + phi_k), circular with period pi (both profiles have the
/// same number of columns, spanning [0, pi)) — DESIGN Appendix A step 2.
std::vector<double> circularCorrelation(const std::vector<double>& h, const std::vector<double>& m);

/// Step 2: local maxima phi of c (refined to sub-column precision by a parabola), strongest
/// first, each giving the heading candidates phi and phi + pi (normalised to (-pi, pi]).
std::vector<OrientationCandidate> findOrientationCandidates(const std::vector<double>& h,
                                                            const std::vector<double>& m,
                                                            const OrientationConfig& config);

}  // namespace houghloc
