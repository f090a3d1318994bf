#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "field_models/distance_grid.h"
#include "field_models/field_model.h"
#include "localization/feature_lookup.h"
#include "localization/hough_transform.h"

namespace houghloc {

struct MapSignatureConfig {
  HoughConfig hough;                  ///< must equal the sensor transform's discretisation
  double sample_spacing_m = 0.02;     ///< map lines and arcs are sampled like sensor points
  double dominant_share = 0.3;        ///< maxima of m(theta) above this share of the top one
  double mask_min_line_m = 0.25;      ///< a map rho row counts as "line" from this much line
  double evidence_spacing_m = 0.10;   ///< spacing of the samples used for negative evidence
  double lookup_resolution_m = 0.05;  ///< cells of the nearest-feature lookup (refinement)
  DistanceGridConfig grid;            ///< scoring grid (shared with the exhaustive baseline)
};

/// Everything about a map that the localizer needs, computed once per map (paper: HT_M and
/// m(theta); DESIGN Appendix A step 2): the map's Hough transform built from sampled lines and
/// arcs, its normalised orientation profile, the dominant directions theta_mu with their rho
/// columns as line masks (step 3), the distance grid for scoring and the feature lookup for
/// refinement.
class MapSignature {
 public:
  explicit MapSignature(const FieldModel& field, const MapSignatureConfig& config = {});

  const FieldModel& field() const { return field_; }
  const MapSignatureConfig& config() const { return config_; }
  const HoughTransform& transform() const { return transform_; }
  /// m(theta) = sum_rho HT_M(theta, rho)^2, zero mean and unit norm (step 2).
  const std::vector<double>& profile() const { return profile_; }
  /// Dominant map directions theta_mu in [0, pi) (maxima of m), strongest first.
  const std::vector<double>& dominantDirections() const { return dominant_; }
  /// Line mask of the map's rho column at dominantDirections()[k]: 1 where a map line lies, in
  /// rows of houghColumn(.., rhoMax()).
  const std::vector<float>& lineMask(int k) const { return masks_[k]; }
  double rhoMax() const { return rho_max_; }

  const DistanceGrid& grid() const { return grid_; }
  const FeatureLookup& features() const { return features_; }
  /// Points every evidence_spacing_m along all lines and arcs, field frame (negative evidence),
  /// ordered by square buckets of kEvidenceBucketM so that a region is cheap to visit.
  const std::vector<Eigen::Vector2d>& evidenceSamples() const { return evidence_; }
  /// Calls f(p_field) for every evidence sample in the buckets overlapping the box [lo, hi]
  /// (a superset of the samples inside it).
  template <typename F>
  void forEachEvidenceSample(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, F&& f) const {
    const BucketRange cols = bucketRange(lo.x(), hi.x(), bucket_origin_.x(), bucket_cols_);
    const BucketRange rows = bucketRange(lo.y(), hi.y(), bucket_origin_.y(), bucket_rows_);
    for (int r = rows.first; r <= rows.last; ++r) {
      const int begin = bucket_start_[r * bucket_cols_ + cols.first];
      const int end = bucket_start_[r * bucket_cols_ + cols.last + 1];
      for (int i = begin; i < end; ++i) f(evidence_[i]);
    }
  }
  static constexpr double kEvidenceBucketM = 1.0;  ///< bucket size of the evidence samples
  /// True when the map maps onto itself under p -> -p (every standard field): a pose and its
  /// twin (-x, -y, theta + pi) then explain any frame equally well.
  bool pointSymmetric() const { return point_symmetric_; }
  /// Full circles of the map (the centre circle), for the circle step.
  const std::vector<Arc2>& circles() const { return circles_; }

 private:
  struct BucketRange {
    int first = 0, last = -1;  ///< buckets first..last; empty when first > last
  };
  /// The buckets along one axis that [lo, hi] overlaps, clamped to the `count` buckets from
  /// `origin`; empty when the interval misses them or is NaN (a pose far off the field).
  static BucketRange bucketRange(double lo, double hi, double origin, int count) {
    const double first = std::floor((lo - origin) / kEvidenceBucketM);
    const double last = std::floor((hi - origin) / kEvidenceBucketM);
    if (!(first <= last) || last < 0.0 || first >= count) return {};
    return {static_cast<int>(std::max(first, 0.0)), static_cast<int>(std::min(last, count - 1.0))};
  }
  void bucketEvidence(const std::vector<Eigen::Vector2d>& samples);

  FieldModel field_;
  MapSignatureConfig config_;
  double rho_max_ = 0.0;
  HoughTransform transform_;
  std::vector<double> profile_;
  std::vector<double> dominant_;
  std::vector<std::vector<float>> masks_;
  DistanceGrid grid_;
  FeatureLookup features_;
  std::vector<Eigen::Vector2d> evidence_;
  Eigen::Vector2d bucket_origin_ = Eigen::Vector2d::Zero();
  int bucket_cols_ = 0, bucket_rows_ = 0;
  std::vector<int> bucket_start_;  ///< CSR offsets into evidence_, row-major, one extra at the end
  std::vector<Arc2> circles_;
  bool point_symmetric_ = false;
};

/// Points along every segment, arc and mark bar of `field` at `spacing_m`, weight 1 (field frame).
WeightedPoints sampleMapLines(const FieldModel& field, double spacing_m, bool include_marks);

/// h(theta) = sum_rho HT(theta, rho)^2 per column, then zero mean and unit norm (all zeros when
/// the profile is flat, e.g. for a single point) — DESIGN Appendix A step 2.
std::vector<double> orientationProfile(const HoughTransform& transform);

}  // namespace houghloc
