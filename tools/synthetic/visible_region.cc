#include "tools/synthetic/visible_region.h"

#include <algorithm>
#include <cmath>

namespace houghloc {

double visibleRange(double phi, double max_range, const std::vector<Occluder>& occluders) {
  double r = max_range;
  for (const Occluder& o : occluders) {
    const double dist = o.center.norm();
    if (dist <= o.radius_m) return 0.0;
    const double half = std::asin(o.radius_m / dist);
    const double centre = std::atan2(o.center.y(), o.center.x());
    if (std::abs(std::remainder(phi - centre, 2.0 * M_PI)) <= half) {
      r = std::min(r, dist - o.radius_m);
    }
  }
  return r;
}

namespace {

GroundPolygon clipByEdge(const GroundPolygon& poly, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  GroundPolygon out;
  auto inside = [&](const Eigen::Vector2d& p) {
    return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x()) >= 0.0;
  };
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& cur = poly[i];
    const Eigen::Vector2d& prev = poly[(i + poly.size() - 1) % poly.size()];
    const bool in_cur = inside(cur), in_prev = inside(prev);
    if (in_cur != in_prev) {
      const Eigen::Vector2d d = cur - prev, e = b - a;
      const double denom = d.x() * e.y() - d.y() * e.x();
      const double t = ((a.x() - prev.x()) * e.y() - (a.y() - prev.y()) * e.x()) / denom;
      out.push_back(prev + t * d);
    }
    if (in_cur) out.push_back(cur);
  }
  return out;
}

}  // namespace

bool wedgeVisible(const Eigen::Vector2d& p, double half_angle, double min_range, double max_range,
                  const std::vector<Occluder>& occluders) {
  const double r = p.norm();
  if (r < min_range || r > max_range) return false;
  const double phi = std::atan2(p.y(), p.x());
  if (std::abs(phi) > half_angle) return false;
  return r <= visibleRange(phi, max_range, occluders);
}

GroundPolygon visibleRegion(double half_angle, double min_range, double max_range,
                            const std::vector<Occluder>& occluders, const GroundPolygon& clip) {
  std::vector<double> angles;
  const int steps = std::max(2, static_cast<int>(std::ceil(2.0 * half_angle / 0.035)));
  for (int k = 0; k <= steps; ++k) angles.push_back(-half_angle + 2.0 * half_angle * k / steps);
  for (const Occluder& o : occluders) {
    const double dist = o.center.norm();
    if (dist <= o.radius_m) continue;
    const double half = std::asin(o.radius_m / dist);
    const double centre = std::atan2(o.center.y(), o.center.x());
    for (double edge : {centre - half, centre + half}) {
      for (double eps : {-1e-4, 1e-4}) {
        if (std::abs(edge + eps) < half_angle) angles.push_back(edge + eps);
      }
    }
  }
  std::sort(angles.begin(), angles.end());
  GroundPolygon poly;
  for (double phi : angles) {  // outer boundary, counter-clockwise
    const double r = std::max(min_range, visibleRange(phi, max_range, occluders));
    poly.emplace_back(r * std::cos(phi), r * std::sin(phi));
  }
  for (auto it = angles.rbegin(); it != angles.rend(); ++it) {  // inner arc back
    poly.emplace_back(min_range * std::cos(*it), min_range * std::sin(*it));
  }
  for (std::size_t i = 0; i < clip.size() && !poly.empty(); ++i) {
    poly = clipByEdge(poly, clip[i], clip[(i + 1) % clip.size()]);
  }
  return poly;
}

}  // namespace houghloc
