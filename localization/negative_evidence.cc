#include "localization/negative_evidence.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "field_models/line_features.h"

namespace houghloc {

double distanceToBoundary(const GroundPolygon& poly, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = poly.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    best = std::min(best, Segment2{poly[j], poly[i]}.distanceTo(p));
  }
  return best;
}

VisibilityEvidence::VisibilityEvidence(const GroundPoints& frame, const WeightedPoints& points,
                                       const NegativeEvidenceConfig& config)
    : config_(config) {
  if (!config.enabled) return;
  std::vector<GroundPolygon> polygons;
  for (const GroundPolygon& poly : frame.visible_regions) {
    bool valid = poly.size() >= 3;
    for (const auto& v : poly) valid &= v.allFinite() && v.norm() < 100.0;  // ground, not sky
    if (valid) polygons.push_back(poly);
  }
  if (polygons.empty()) return;
  edge_ = FieldEdgeEvidence(frame, config.field_edge);
  rasterise(polygons);
  // Mark cells within seen_radius_m of a point; count the occupied ones for the line length.
  const int reach = static_cast<int>(std::ceil(config.seen_radius_m / config.raster_m));
  std::vector<char> occupied(cells_.size(), 0);
  int occupied_count = 0;
  for (const auto& p : points.points) {
    const int c = static_cast<int>(std::floor((p.x() - origin_.x()) / config.raster_m));
    const int r = static_cast<int>(std::floor((p.y() - origin_.y()) / config.raster_m));
    if (c < 0 || r < 0 || c >= cols_ || r >= rows_) continue;
    char& o = occupied[static_cast<std::size_t>(r) * cols_ + c];
    occupied_count += o == 0;
    if (o) continue;
    o = 1;
    for (int rr = std::max(0, r - reach); rr <= std::min(rows_ - 1, r + reach); ++rr) {
      for (int cc = std::max(0, c - reach); cc <= std::min(cols_ - 1, c + reach); ++cc) {
        cells_[static_cast<std::size_t>(rr) * cols_ + cc] |= 4;
      }
    }
  }
  // Seen line length ~ occupied cells * cell size; density converts metres to point weight.
  density_ = occupied_count > 0 ? points.totalWeight() / (occupied_count * config.raster_m) : 0.0;
  const int stride =
      std::max(1, static_cast<int>(std::lround(config.green_spacing_m / config.raster_m)));
  green_cell_area_ = (stride * config.raster_m) * (stride * config.raster_m);
  for (int r = stride / 2; r < rows_; r += stride) {
    for (int c = stride / 2; c < cols_; c += stride) {
      if (cells_[static_cast<std::size_t>(r) * cols_ + c] & 1) {
        const Eigen::Vector2d g = origin_ + config.raster_m * Eigen::Vector2d(c + 0.5, r + 0.5);
        green_x_.push_back(g.x());
        green_y_.push_back(g.y());
        green_lo_ = green_lo_.cwiseMin(g);
        green_hi_ = green_hi_.cwiseMax(g);
      }
    }
  }
  // Box of the cells where an unseen line can count (inside with margin, no point near): only
  // map samples that a pose puts there matter.
  int c_lo = cols_, c_hi = -1, r_lo = rows_, r_hi = -1;
  for (int r = 0; r < rows_; ++r) {
    for (int c = 0; c < cols_; ++c) {
      if ((cells_[static_cast<std::size_t>(r) * cols_ + c] & 6) != 2) continue;
      c_lo = std::min(c_lo, c);
      c_hi = std::max(c_hi, c);
      r_lo = std::min(r_lo, r);
      r_hi = std::max(r_hi, r);
    }
  }
  if (c_hi >= 0) {
    unseen_lo_ = origin_ + config.raster_m * Eigen::Vector2d(c_lo, r_lo);
    unseen_hi_ = origin_ + config.raster_m * Eigen::Vector2d(c_hi + 1, r_hi + 1);
  }
  empty_ = false;
}

void VisibilityEvidence::rasterise(const std::vector<GroundPolygon>& polygons) {
  const double cell = config_.raster_m;
  const int margin = static_cast<int>(std::ceil(config_.margin_m / cell));
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const auto& poly : polygons) {
    for (const auto& v : poly) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  }
  origin_ = lo - Eigen::Vector2d::Constant(config_.seen_radius_m + cell);
  cols_ = static_cast<int>((hi.x() - origin_.x() + config_.seen_radius_m + cell) / cell) + 1;
  rows_ = static_cast<int>((hi.y() - origin_.y() + config_.seen_radius_m + cell) / cell) + 1;
  cells_.assign(static_cast<std::size_t>(cols_) * rows_, 0);
  // Scanline fill (even-odd per polygon) at the cell centres.
  std::vector<double> crossings;
  for (const auto& poly : polygons) {
    for (int r = 0; r < rows_; ++r) {
      const double y = origin_.y() + (r + 0.5) * cell;
      crossings.clear();
      for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const Eigen::Vector2d& a = poly[i];
        const Eigen::Vector2d& b = poly[j];
        if ((a.y() > y) != (b.y() > y)) {
          crossings.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
        }
      }
      std::sort(crossings.begin(), crossings.end());
      for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
        const int c0 =
            std::max(0, static_cast<int>(std::ceil((crossings[k] - origin_.x()) / cell - 0.5)));
        const int c1 = std::min(
            cols_ - 1, static_cast<int>(std::floor((crossings[k + 1] - origin_.x()) / cell - 0.5)));
        for (int c = c0; c <= c1; ++c) cells_[static_cast<std::size_t>(r) * cols_ + c] |= 1;
      }
    }
  }
  // Erode the region by the margin (square structuring element, separable: rows, then
  // columns): bit 1. A cell survives a pass when the run of region cells through it reaches
  // `margin` cells on both sides; runs are counted once per cell instead of rescanning the window.
  const int window = 2 * margin + 1;
  std::vector<unsigned char> across(cells_.size(), 0);
  for (int r = 0; r < rows_; ++r) {
    const unsigned char* row = &cells_[static_cast<std::size_t>(r) * cols_];
    int run = 0;  // region cells ending at c
    for (int c = 0; c < cols_; ++c) {
      run = (row[c] & 1) ? run + 1 : 0;
      if (run >= window) across[static_cast<std::size_t>(r) * cols_ + c - margin] = 1;
    }
  }
  std::vector<int> runs(cols_, 0);  // per column: `across` cells ending at row r
  for (int r = 0; r < rows_; ++r) {
    const unsigned char* row = &across[static_cast<std::size_t>(r) * cols_];
    for (int c = 0; c < cols_; ++c) {
      runs[c] = row[c] ? runs[c] + 1 : 0;
      if (runs[c] >= window) cells_[static_cast<std::size_t>(r - margin) * cols_ + c] |= 2;
    }
  }
}

double VisibilityEvidence::unseenLineLength(const Pose2& field_T_robot,
                                            const MapSignature& map) const {
  if (empty_ || !(unseen_lo_.x() <= unseen_hi_.x())) return 0.0;
  // Only the map samples that can fall into a counting cell matter: the corners of those cells'
  // box in the field frame (padded against rounding) bound the buckets to visit.
  const double c_f = std::cos(field_T_robot.theta), s_f = std::sin(field_T_robot.theta);
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (int k = 0; k < 4; ++k) {
    const double x = k & 1 ? unseen_hi_.x() : unseen_lo_.x();
    const double y = k & 2 ? unseen_hi_.y() : unseen_lo_.y();
    const Eigen::Vector2d q(c_f * x - s_f * y + field_T_robot.x,
                            s_f * x + c_f * y + field_T_robot.y);
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  lo -= Eigen::Vector2d::Constant(1e-6);
  hi += Eigen::Vector2d::Constant(1e-6);
  const Pose2 robot_T_field = field_T_robot.inverse();
  const double c = std::cos(robot_T_field.theta), s = std::sin(robot_T_field.theta);
  const double inv = 1.0 / config_.raster_m;
  int unseen = 0;
  map.forEachEvidenceSample(lo, hi, [&](const Eigen::Vector2d& p) {
    const double gx = (c * p.x() - s * p.y() + robot_T_field.x - origin_.x()) * inv;
    const double gy = (s * p.x() + c * p.y() + robot_T_field.y - origin_.y()) * inv;
    if (!(gx >= 0.0 && gy >= 0.0 && gx < cols_ && gy < rows_)) return;  // outside, or NaN
    const unsigned char v = cells_[static_cast<int>(gy) * cols_ + static_cast<int>(gx)];
    unseen += (v & 6) == 2;  // inside with margin, no point near
  });
  return unseen * map.config().evidence_spacing_m;
}

double VisibilityEvidence::greenOutsideCarpet(const Pose2& field_T_robot,
                                              const FieldModel& field) const {
  const double hx = field.outerHalfLength() + config_.outside_margin_m;
  const double hy = field.outerHalfWidth() + config_.outside_margin_m;
  const double c = std::cos(field_T_robot.theta), s = std::sin(field_T_robot.theta);
  // The samples lie in their box: when its corners are all on the carpet (with a margin against
  // rounding), so is every sample.
  bool all_inside = !green_x_.empty();
  for (int k = 0; k < 4 && all_inside; ++k) {
    const double gx = k & 1 ? green_hi_.x() : green_lo_.x();
    const double gy = k & 2 ? green_hi_.y() : green_lo_.y();
    const double x = c * gx - s * gy + field_T_robot.x;
    const double y = s * gx + c * gy + field_T_robot.y;
    all_inside = std::abs(x) < hx - 1e-6 && std::abs(y) < hy - 1e-6;
  }
  if (all_inside) return 0.0;
  int outside = 0;
  const double tx = field_T_robot.x, ty = field_T_robot.y;
  const double* gx = green_x_.data();
  const double* gy = green_y_.data();
  const std::size_t n = green_x_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double x = c * gx[i] - s * gy[i] + tx;
    const double y = s * gx[i] + c * gy[i] + ty;
    outside += (std::abs(x) > hx) | (std::abs(y) > hy);
  }
  return outside * green_cell_area_;
}

bool VisibilityEvidence::keepEdgeIfAnyFits(const std::vector<Pose2>& poses,
                                           const FieldModel& field) {
  if (edgeEmpty()) return false;
  for (const Pose2& pose : poses) {
    const double cost = edge_.meanCost(pose, field.outerHalfLength(), field.outerHalfWidth());
    if (cost < edge_.maxBestCost()) return true;
  }
  edge_.clear();
  return false;
}

double VisibilityEvidence::edgePenalty(const Pose2& field_T_robot, const FieldModel& field) const {
  if (empty_ || edge_.empty()) return 0.0;
  return density_ *
         edge_.penaltyMetres(field_T_robot, field.outerHalfLength(), field.outerHalfWidth());
}

VisibilityEvidence::CheapTerms VisibilityEvidence::cheapTerms(const Pose2& field_T_robot,
                                                              const FieldModel& field) const {
  return cheapTerms(field_T_robot, field, edgePenalty(field_T_robot, field));
}

VisibilityEvidence::CheapTerms VisibilityEvidence::cheapTerms(const Pose2& field_T_robot,
                                                              const FieldModel& field,
                                                              double edge) const {
  CheapTerms terms;
  if (empty_) return terms;
  terms.green_m2 = greenOutsideCarpet(field_T_robot, field);
  terms.edge = edge;
  terms.bound = density_ * config_.outside_weight * terms.green_m2 + terms.edge;
  return terms;
}

double VisibilityEvidence::penalty(const Pose2& field_T_robot, const MapSignature& map) const {
  return penalty(field_T_robot, map, cheapTerms(field_T_robot, map.field()));
}

double VisibilityEvidence::penalty(const Pose2& field_T_robot, const MapSignature& map,
                                   const CheapTerms& cheap) const {
  if (empty_) return 0.0;
  return density_ * (config_.line_weight * unseenLineLength(field_T_robot, map) +
                     config_.outside_weight * cheap.green_m2) +
         cheap.edge;
}

}  // namespace houghloc
