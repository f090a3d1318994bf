#pragma once

#include <vector>

#include "localization/hough_transform.h"
#include "localization/map_signature.h"

namespace houghloc {

struct TranslationConfig {
  double min_line_weight = 4.0;  ///< a constraint needs this much point weight on map lines
  double relative_share = 0.2;   ///< ... and this share of the direction's strongest shift
  int max_peaks = 12;            ///< shifts kept per direction, strongest first
  double suppression_m = 0.12;   ///< non-maximum suppression window of the shift d
};

/// T_x cos theta_mu + T_y sin theta_mu = d (DESIGN Appendix A step 3): the robot position
/// projected on the normal of map direction theta_mu.
struct TranslationConstraint {
  int direction = 0;      ///< index into MapSignature::dominantDirections()
  double theta_mu = 0.0;  ///< rad, normal direction of the map lines, [0, pi)
  double d_m = 0.0;       ///< m
  double support = 0.0;   ///< point weight that the shift puts on map lines
};

/// c(d) = sum_rho h'(rho) m'(rho + d): the sensor column at theta_mu - theta_R against the map's
/// line mask at theta_mu, for |d| <= max_abs_d (rows of rho_step). Sparse in the mask's rows.
std::vector<double> columnCorrelation(const std::vector<float>& sensor_column,
                                      const std::vector<float>& map_mask, int max_shift_rows);

/// Step 3 for one heading candidate theta_R and one dominant map direction: the maxima of the
/// column correlation as translation constraints, strongest first.
std::vector<TranslationConstraint> findTranslationConstraints(const WeightedPoints& sensor,
                                                              const MapSignature& map,
                                                              int direction, double theta_r,
                                                              const TranslationConfig& config);

}  // namespace houghloc
