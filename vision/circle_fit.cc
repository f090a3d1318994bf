#include "vision/circle_fit.h"

#include <Eigen/Dense>
#include <cmath>

namespace houghloc {

bool fitCircleFixedRadius(const std::vector<Eigen::Vector2d>& points, double radius_m,
                          Eigen::Vector2d* center) {
  if (points.size() < 3) return false;
  // Kasa: x^2 + y^2 + D x + E y + F = 0, linear in (D, E, F).
  Eigen::MatrixXd a(points.size(), 3);
  Eigen::VectorXd rhs(points.size());
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d p = points[i] - mean;  // centred for conditioning
    a.row(static_cast<long>(i)) << p.x(), p.y(), 1.0;
    rhs(static_cast<long>(i)) = -p.squaredNorm();
  }
  const Eigen::Vector3d x = a.colPivHouseholderQr().solve(rhs);
  Eigen::Vector2d c = mean + Eigen::Vector2d(-0.5 * x(0), -0.5 * x(1));
  if (!c.allFinite()) return false;
  // The free fit's centre of a short arc moves along the arc's normal with its radius: pull it
  // to the given radius along the line from the arc's middle before refining.
  const Eigen::Vector2d toward = c - mean;
  if (toward.norm() > 1e-9) c = mean + toward.normalized() * radius_m;
  for (int it = 0; it < 6; ++it) {
    Eigen::Matrix2d h = Eigen::Matrix2d::Zero();
    Eigen::Vector2d g = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& p : points) {
      const Eigen::Vector2d d = c - p;
      const double distance = d.norm();
      if (distance < 1e-9) continue;
      const Eigen::Vector2d j = d / distance;  // d(distance - r) / dc
      h += j * j.transpose();
      g += j * (distance - radius_m);
    }
    const Eigen::Vector2d step = -h.ldlt().solve(g);
    if (!step.allFinite()) return false;
    c += step;
  }
  *center = c;
  return true;
}

}  // namespace houghloc
