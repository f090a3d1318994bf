#include "tools/render/line_painter.h"

#include <algorithm>
#include <cmath>

namespace houghloc {
namespace {

/// Fraction of the interval [c - f/2, c + f/2] inside [lo, hi] (a 1-D box filter).
inline float overlap(float c, float f, float lo, float hi) {
  f = std::max(f, 1e-5f);
  const float inside = std::min(c + 0.5f * f, hi) - std::max(c - 0.5f * f, lo);
  return std::clamp(inside / f, 0.0f, 1.0f);
}

}  // namespace

void LinePainter::addBar(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double width,
                         double cap, int tag) {
  Item it;
  it.kind = Item::Kind::kBar;
  it.a = a.cast<float>();
  const Eigen::Vector2d d = b - a;
  it.length = static_cast<float>(d.norm());
  it.dir =
      it.length > 0.0f ? Eigen::Vector2f((d / d.norm()).cast<float>()) : Eigen::Vector2f::UnitX();
  it.cap = static_cast<float>(cap);
  it.half_width = static_cast<float>(0.5 * width);
  it.tag = tag;
  items_.push_back(it);
}

void LinePainter::addArc(const Arc2& arc, double width, int tag) {
  Item it;
  it.kind = Item::Kind::kRing;
  it.a = arc.center.cast<float>();
  it.radius = static_cast<float>(arc.radius);
  it.start = static_cast<float>(arc.start_rad);
  it.sweep = static_cast<float>(arc.sweep_rad);
  it.full = arc.isFullCircle();
  it.half_width = static_cast<float>(0.5 * width);
  it.tag = tag;
  items_.push_back(it);
}

void LinePainter::addDisc(const Eigen::Vector2d& center, double radius, int tag) {
  Item it;
  it.kind = Item::Kind::kDisc;
  it.a = center.cast<float>();
  it.half_width = static_cast<float>(radius);
  it.tag = tag;
  items_.push_back(it);
}

void LinePainter::addField(const FieldModel& field) {
  const double w = field.line_width;
  for (const Segment2& s : field.segments) addBar(s.a, s.b, w, 0.5 * w, 0);
  for (const Arc2& a : field.arcs) addArc(a, w, 0);
  for (const Mark& m : field.marks) {
    if (m.shape == MarkShape::kDot) {
      addDisc(m.center, 0.5 * m.size, 0);
      continue;
    }
    const Eigen::Vector2d hx(0.5 * m.size, 0.0), hy(0.0, 0.5 * m.size);
    addBar(m.center - hx, m.center + hx, w, 0.0, 0);
    addBar(m.center - hy, m.center + hy, w, 0.0, 0);
  }
}

double LinePainter::itemDistance(const Item& it, const Eigen::Vector2d& p) const {
  const Eigen::Vector2d a = it.a.cast<double>();
  switch (it.kind) {
    case Item::Kind::kBar: {
      const Eigen::Vector2d d = it.dir.cast<double>();
      const double s = std::clamp((p - a).dot(d), -double(it.cap), double(it.length + it.cap));
      return (p - (a + s * d)).norm() - it.half_width;
    }
    case Item::Kind::kRing:
      return std::abs((p - a).norm() - it.radius) - it.half_width;  // ignores the arc's ends
    case Item::Kind::kDisc:
      return (p - a).norm() - it.half_width;
  }
  return 0.0;
}

void LinePainter::build(const Eigen::Vector2d& min, const Eigen::Vector2d& max, double cell_m,
                        double reach_m) {
  min_ = min;
  cell_ = cell_m;
  cols_ = std::max(1, static_cast<int>(std::ceil((max.x() - min.x()) / cell_m)));
  rows_ = std::max(1, static_cast<int>(std::ceil((max.y() - min.y()) / cell_m)));
  std::vector<std::vector<int>> cells(static_cast<size_t>(cols_) * rows_);
  const double half_diagonal = 0.5 * std::sqrt(2.0) * cell_m;
  for (int i = 0; i < static_cast<int>(items_.size()); ++i) {
    for (int r = 0; r < rows_; ++r) {
      for (int c = 0; c < cols_; ++c) {
        const Eigen::Vector2d centre = min + cell_m * Eigen::Vector2d(c + 0.5, r + 0.5);
        if (itemDistance(items_[i], centre) <= half_diagonal + reach_m) {
          cells[static_cast<size_t>(r) * cols_ + c].push_back(i);
        }
      }
    }
  }
  cell_start_.assign(1, 0);
  cell_items_.clear();
  for (const auto& cell : cells) {
    cell_items_.insert(cell_items_.end(), cell.begin(), cell.end());
    cell_start_.push_back(static_cast<int>(cell_items_.size()));
  }
}

float LinePainter::itemCoverage(const Item& it, const Eigen::Vector2f& g, const Footprint& fp,
                                float offset) const {
  const Eigen::Vector2f rel = g - it.a;
  const float hw = it.half_width + offset;
  switch (it.kind) {
    case Item::Kind::kBar: {
      const Eigen::Vector2f n(-it.dir.y(), it.dir.x());
      const float across = overlap(rel.dot(n), fp.along(n), -hw, hw);
      if (across <= 0.0f) return 0.0f;
      return across * overlap(rel.dot(it.dir), fp.along(it.dir), -it.cap, it.length + it.cap);
    }
    case Item::Kind::kRing: {
      const float rho = rel.norm();
      if (rho <= 1e-6f) return 0.0f;
      const Eigen::Vector2f radial = rel / rho;
      const float cov = overlap(rho - it.radius, fp.along(radial), -hw, hw);
      if (cov <= 0.0f || it.full) return cov;
      float offset_angle = std::atan2(rel.y(), rel.x()) - it.start;
      offset_angle -= 6.2831853f * std::floor(offset_angle / 6.2831853f);
      return offset_angle <= it.sweep ? cov : 0.0f;
    }
    case Item::Kind::kDisc: {
      const float rho = rel.norm();
      const Eigen::Vector2f radial =
          rho > 1e-6f ? Eigen::Vector2f(rel / rho) : Eigen::Vector2f(1, 0);
      return overlap(rho, fp.along(radial), -hw, hw);
    }
  }
  return 0.0f;
}

PaintCoverage LinePainter::coverage(const Eigen::Vector2f& g, const Footprint& fp,
                                    float width_offset_m) const {
  PaintCoverage best;
  const int c = static_cast<int>(std::floor((g.x() - min_.x()) / cell_));
  const int r = static_cast<int>(std::floor((g.y() - min_.y()) / cell_));
  if (c < 0 || r < 0 || c >= cols_ || r >= rows_) return best;
  const int cell = r * cols_ + c;
  for (int k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
    const Item& it = items_[cell_items_[k]];
    const float cov = itemCoverage(it, g, fp, width_offset_m);
    if (cov > best.coverage) {
      best.coverage = cov;
      best.tag = it.tag;
    }
  }
  return best;
}

}  // namespace houghloc
