#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_models/ground_points.h"
#include "field_models/pose2.h"
#include "localization/field_edge_evidence.h"
#include "localization/hough_transform.h"
#include "localization/map_signature.h"

namespace houghloc {

/// Beyond the paper: lines the map predicts inside the seen ground region where no point was
/// found, and green seen where the hypothesis puts the outside of the carpet, count against a
/// hypothesis (DESIGN §8, issue "go beyond positive evidence").
struct NegativeEvidenceConfig {
  bool enabled = true;
  double margin_m = 0.3;          ///< expected lines count only this far inside the region
  double seen_radius_m = 0.2;     ///< an expected line sample is seen if a point is this close
  double line_weight = 0.5;       ///< penalty per unseen metre, in metres of seen line
  double outside_weight = 1.0;    ///< penalty per m^2 of green beyond the carpet, in m of line
  double outside_margin_m = 0.3;  ///< green up to this far beyond the carpet is tolerated
  double green_spacing_m = 0.25;  ///< lattice spacing of the visible-region samples
  double raster_m = 0.1;          ///< cell of the rasterised visible region and seen points
  FieldEdgeConfig field_edge;     ///< the carpet's edge at long range (GroundPoints::field_edge)
};

/// The per-frame part of the negative evidence: the visible region and where points were seen.
class VisibilityEvidence {
 public:
  VisibilityEvidence(const GroundPoints& frame, const WeightedPoints& points,
                     const NegativeEvidenceConfig& config);

  bool empty() const { return empty_; }
  /// True when the frame has no usable field-edge samples.
  bool edgeEmpty() const { return empty_ || edge_.empty(); }
  /// Drops the field-edge samples unless one of the poses explains them (mean cost below
  /// FieldEdgeConfig::max_best_cost); returns whether they are kept.
  bool keepEdgeIfAnyFits(const std::vector<Pose2>& poses, const FieldModel& field);
  /// Point weight per metre of seen line (converts lengths into the score's units).
  double pointDensity() const { return density_; }
  /// Metres of map line predicted at least margin_m inside the visible region without a point.
  double unseenLineLength(const Pose2& field_T_robot, const MapSignature& map) const;
  /// Area (m^2) of the visible region that the pose puts beyond the carpet plus outside_margin_m.
  double greenOutsideCarpet(const Pose2& field_T_robot, const FieldModel& field) const;
  /// Penalty in point weight of the field-edge samples alone (cheap: a few ray casts).
  double edgePenalty(const Pose2& field_T_robot, const FieldModel& field) const;
  /// The cheap terms of penalty(), for callers that decide on them before paying for the
  /// unseen lines: green beyond the carpet (m^2) and edgePenalty(); `bound` = density *
  /// outside_weight * green + edge is a lower bound of penalty().
  struct CheapTerms {
    double green_m2 = 0.0, edge = 0.0, bound = 0.0;
  };
  CheapTerms cheapTerms(const Pose2& field_T_robot, const FieldModel& field) const;
  /// The same, with `edge` = edgePenalty(field_T_robot, field) already computed (a caller can
  /// first decide on the edge alone, a lower bound of `bound`).
  CheapTerms cheapTerms(const Pose2& field_T_robot, const FieldModel& field, double edge) const;
  /// Penalty in point weight: density * (line_weight * unseen + outside_weight * green area)
  /// plus edgePenalty(); the second form takes the cheap terms already computed for the pose.
  double penalty(const Pose2& field_T_robot, const MapSignature& map) const;
  double penalty(const Pose2& field_T_robot, const MapSignature& map,
                 const CheapTerms& cheap) const;

 private:
  void rasterise(const std::vector<GroundPolygon>& polygons);

  NegativeEvidenceConfig config_;
  bool empty_ = true;
  FieldEdgeEvidence edge_;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  int cols_ = 0, rows_ = 0;
  /// Per cell: bit 0 inside the region, bit 1 inside with margin, bit 2 near a seen point.
  std::vector<unsigned char> cells_;
  /// Lattice samples inside the region, robot frame; x and y apart so that the count of samples
  /// beyond the carpet is a loop the compiler vectorises.
  std::vector<double> green_x_, green_y_;
  Eigen::Vector2d green_lo_ = Eigen::Vector2d::Constant(1e300);  ///< box of the green samples
  Eigen::Vector2d green_hi_ = Eigen::Vector2d::Constant(-1e300);
  /// Box of the cells that count for unseenLineLength (robot frame; empty when lo > hi).
  Eigen::Vector2d unseen_lo_ = Eigen::Vector2d::Constant(1e300);
  Eigen::Vector2d unseen_hi_ = Eigen::Vector2d::Constant(-1e300);
  double green_cell_area_ = 0.0;  ///< m^2 per green sample
  double density_ = 0.0;
};

/// Distance from p to the polygon's boundary.
double distanceToBoundary(const GroundPolygon& polygon, const Eigen::Vector2d& p);

}  // namespace houghloc
