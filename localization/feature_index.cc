#include "localization/feature_index.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace houghloc {
namespace {

constexpr double kTiny = 1e-9;

/// Point-to-point association, used at segment and arc ends and for dots.
Association toPoint(const Eigen::Vector2d& point, const Eigen::Vector2d& p,
                    const Eigen::Vector2d& fallback_normal) {
  Association out;
  const Eigen::Vector2d v = p - point;
  out.distance_m = v.norm();
  out.normal = out.distance_m > kTiny ? Eigen::Vector2d(v / out.distance_m) : fallback_normal;
  out.residual_m = out.distance_m;
  return out;
}

std::vector<LinePrimitive> makePrimitives(const FieldModel& field) {
  std::vector<LinePrimitive> out;
  auto add_segment = [&](const Segment2& s, FeatureRef ref) {
    LinePrimitive p;
    p.kind = LinePrimitive::Kind::kSegment;
    p.feature = ref;
    p.a = s.a;
    p.length = s.length();
    if (p.length > kTiny) p.direction = (s.b - s.a) / p.length;
    out.push_back(p);
  };
  for (int i = 0; i < static_cast<int>(field.segments.size()); ++i) {
    add_segment(field.segments[i], {FeatureKind::kSegment, i});
  }
  for (int i = 0; i < static_cast<int>(field.arcs.size()); ++i) {
    const Arc2& arc = field.arcs[i];
    LinePrimitive p;
    p.kind = LinePrimitive::Kind::kArc;
    p.feature = {FeatureKind::kArc, i};
    p.a = arc.center;
    p.length = arc.radius;
    p.start_rad = arc.start_rad;
    p.sweep_rad = arc.sweep_rad;
    p.full_circle = arc.isFullCircle();
    out.push_back(p);
  }
  for (int i = 0; i < static_cast<int>(field.marks.size()); ++i) {
    const Mark& m = field.marks[i];
    const FeatureRef ref{FeatureKind::kMark, i};
    if (m.shape == MarkShape::kDot) {
      LinePrimitive p;
      p.kind = LinePrimitive::Kind::kDisc;
      p.feature = ref;
      p.a = m.center;
      p.length = 0.5 * m.size;
      out.push_back(p);
      continue;
    }
    const double h = 0.5 * m.size;
    add_segment({m.center - Eigen::Vector2d(h, 0.0), m.center + Eigen::Vector2d(h, 0.0)}, ref);
    add_segment({m.center - Eigen::Vector2d(0.0, h), m.center + Eigen::Vector2d(0.0, h)}, ref);
  }
  return out;
}

}  // namespace

Association associateWith(const LinePrimitive& prim, const Eigen::Vector2d& p) {
  switch (prim.kind) {
    case LinePrimitive::Kind::kSegment: {
      const Eigen::Vector2d normal(-prim.direction.y(), prim.direction.x());
      const double t = (p - prim.a).dot(prim.direction);
      if (t <= 0.0) return toPoint(prim.a, p, normal);
      if (t >= prim.length) return toPoint(prim.a + prim.length * prim.direction, p, normal);
      Association out;
      out.normal = normal;
      out.residual_m = normal.dot(p - prim.a);
      out.distance_m = std::abs(out.residual_m);
      return out;
    }
    case LinePrimitive::Kind::kArc: {
      const Eigen::Vector2d v = p - prim.a;
      const double rho = v.norm();
      const Eigen::Vector2d radial =
          rho > kTiny ? Eigen::Vector2d(v / rho) : Eigen::Vector2d::UnitX();
      bool inside = prim.full_circle;
      if (!inside) {
        double offset = std::atan2(v.y(), v.x()) - prim.start_rad;
        offset -= 2.0 * M_PI * std::floor(offset / (2.0 * M_PI));
        inside = offset <= prim.sweep_rad;
      }
      if (inside) {
        Association out;
        out.normal = radial;
        out.residual_m = rho - prim.length;
        out.distance_m = std::abs(out.residual_m);
        return out;
      }
      const auto end = [&](double angle) {
        return Eigen::Vector2d(prim.a +
                               prim.length * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
      };
      const Eigen::Vector2d first = end(prim.start_rad),
                            last = end(prim.start_rad + prim.sweep_rad);
      return toPoint((first - p).squaredNorm() <= (last - p).squaredNorm() ? first : last, p,
                     radial);
    }
    case LinePrimitive::Kind::kDisc: {
      const Eigen::Vector2d v = p - prim.a;
      const double rho = v.norm();
      Association out;
      if (rho <= prim.length) return out;  // on the painted dot: no residual, no direction
      out.normal = v / rho;
      out.residual_m = out.distance_m = rho - prim.length;
      return out;
    }
  }
  return {};
}

FeatureIndex::FeatureIndex(const FieldModel& field, const FeatureIndexConfig& config)
    : config_(config), primitives_(makePrimitives(field)) {
  if (!(config.resolution_m > 0.0)) throw std::invalid_argument("resolution_m must be > 0");
  if (primitives_.size() > 32000) throw std::invalid_argument("map has too many features");
  const double hx = field.outerHalfLength() + config.margin_m;
  const double hy = field.outerHalfWidth() + config.margin_m;
  origin_ = Eigen::Vector2d(-hx, -hy);
  inv_resolution_ = 1.0 / config.resolution_m;
  cols_ = std::max(1, static_cast<int>(std::ceil(2.0 * hx * inv_resolution_)));
  rows_ = std::max(1, static_cast<int>(std::ceil(2.0 * hy * inv_resolution_)));
  const size_t cells = static_cast<size_t>(cols_) * rows_;
  cell_begin_.assign(1, 0);
  cell_begin_.reserve(cells + 1);
  // A primitive nearest to some point of a cell is within d_min(centre) + 2 * half diagonal of
  // the centre (triangle inequality twice).
  const double reach = std::sqrt(2.0) * config.resolution_m;
  std::vector<std::pair<double, int>> dist(primitives_.size());
  for (int r = 0; r < rows_; ++r) {
    for (int c = 0; c < cols_; ++c) {
      const Eigen::Vector2d centre =
          origin_ + config.resolution_m * Eigen::Vector2d(c + 0.5, r + 0.5);
      for (size_t k = 0; k < primitives_.size(); ++k) {
        dist[k] = {associateWith(primitives_[k], centre).distance_m, static_cast<int>(k)};
      }
      std::sort(dist.begin(), dist.end());
      for (const auto& [d, k] : dist) {
        if (d > dist.front().first + reach) break;
        candidates_.push_back(static_cast<std::int16_t>(k));
      }
      cell_begin_.push_back(static_cast<std::uint32_t>(candidates_.size()));
    }
  }
}

bool FeatureIndex::associate(const Eigen::Vector2d& p_field, Association* out) const {
  if (candidates_.empty() || !p_field.allFinite()) return false;
  const double gx = (p_field.x() - origin_.x()) * inv_resolution_;
  const double gy = (p_field.y() - origin_.y()) * inv_resolution_;
  if (!(gx >= 0.0 && gy >= 0.0 && gx < cols_ && gy < rows_)) return false;
  const size_t cell = static_cast<size_t>(gy) * cols_ + static_cast<size_t>(gx);
  bool found = false;
  for (std::uint32_t i = cell_begin_[cell]; i < cell_begin_[cell + 1]; ++i) {
    const std::int16_t k = candidates_[i];
    const Association a = associateWith(primitives_[k], p_field);
    if (!found || a.distance_m < out->distance_m) {
      *out = a;
      out->primitive = k;
      found = true;
    }
  }
  return found;
}

}  // namespace houghloc
