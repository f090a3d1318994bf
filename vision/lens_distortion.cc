#include "vision/lens_distortion.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "field_models/angles.h"

namespace houghloc {
namespace {

/// Beyond 89 deg off-axis a pinhole image is meaningless; OpenCV's fisheye model divides by z.
constexpr double kMaxPinholeTheta = 89.0 * kPi / 180.0;
constexpr double kMaxFisheyeTheta = 89.5 * kPi / 180.0;
/// Newton stops below this residual in normalized coordinates (~1e-9 px for f ~ 1000 px).
constexpr double kNewtonTolerance = 1e-12;

bool isFinite(const Eigen::Vector2d& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

}  // namespace

LensDistortion::LensDistortion(DistortionModel model, const std::vector<double>& coefficients)
    : model_(model) {
  for (double c : coefficients) {
    if (!std::isfinite(c)) throw std::invalid_argument("distortion coefficient is not finite");
  }
  const std::size_t n = coefficients.size();
  if (model == DistortionModel::kFisheye) {
    if (n != 0 && n != 4) {
      throw std::invalid_argument("fisheye distortion needs 4 coefficients (k1..k4), got " +
                                  std::to_string(n));
    }
  } else {
    if (n != 0 && n != 4 && n != 5 && n != 8 && n != 12 && n != 14) {
      throw std::invalid_argument(
          "pinhole distortion needs 4, 5, 8, 12 or 14 coefficients (OpenCV order), got " +
          std::to_string(n));
    }
    if (n == 14 && (coefficients[12] != 0.0 || coefficients[13] != 0.0)) {
      throw std::invalid_argument("tilted-sensor distortion (tau_x, tau_y) is not supported");
    }
  }
  for (std::size_t i = 0; i < std::min<std::size_t>(n, 12); ++i) k_[i] = coefficients[i];
  const auto nonzero = [](double k) { return k != 0.0; };
  rational_ = std::any_of(k_ + 5, k_ + 8, nonzero);
  thin_prism_ = std::any_of(k_ + 8, k_ + 12, nonzero);
  computeValidFieldAngle();
}

double LensDistortion::radialPinhole(double r) const {
  const double r2 = r * r;
  const double num = 1.0 + r2 * (k_[0] + r2 * (k_[1] + r2 * k_[4]));
  const double den = 1.0 + r2 * (k_[5] + r2 * (k_[6] + r2 * k_[7]));
  return r * num / den;
}

double LensDistortion::radialFisheye(double theta) const {
  const double t2 = theta * theta;
  return theta * (1.0 + t2 * (k_[0] + t2 * (k_[1] + t2 * (k_[2] + t2 * k_[3]))));
}

double LensDistortion::radial(double x) const {
  return model_ == DistortionModel::kFisheye ? radialFisheye(x) : radialPinhole(x);
}

double LensDistortion::radialDerivative(double x) const {
  const double x2 = x * x;
  if (model_ == DistortionModel::kFisheye) {
    return 1.0 + x2 * (3.0 * k_[0] + x2 * (5.0 * k_[1] + x2 * (7.0 * k_[2] + x2 * 9.0 * k_[3])));
  }
  // d/dr [r N(r^2) / D(r^2)] = N/D + 2 r^2 (N' D - N D') / D^2.
  const double n = 1.0 + x2 * (k_[0] + x2 * (k_[1] + x2 * k_[4]));
  const double d = 1.0 + x2 * (k_[5] + x2 * (k_[6] + x2 * k_[7]));
  const double dn = k_[0] + x2 * (2.0 * k_[1] + x2 * 3.0 * k_[4]);
  const double dd = k_[5] + x2 * (2.0 * k_[6] + x2 * 3.0 * k_[7]);
  return n / d + 2.0 * x2 * (dn * d - n * dd) / (d * d);
}

// The valid cone ends where the radial mapping stops increasing (or the rational model's
// denominator vanishes): beyond it two directions share a pixel and inversion is ambiguous.
void LensDistortion::computeValidFieldAngle() {
  const bool fisheye = model_ == DistortionModel::kFisheye;
  const double theta_cap = fisheye ? kMaxFisheyeTheta : kMaxPinholeTheta;
  const int steps = 4000;
  auto arg = [&](double theta) { return fisheye ? theta : std::tan(theta); };
  double previous = 0.0;
  double last_good_theta = 0.0;
  for (int i = 1; i <= steps; ++i) {
    const double theta = theta_cap * i / steps;
    const double x = arg(theta);
    const double r2 = x * x;
    const bool denominator_ok = fisheye || 1.0 + r2 * (k_[5] + r2 * (k_[6] + r2 * k_[7])) > 1e-6;
    const double value = radial(x);
    if (!denominator_ok || !std::isfinite(value) || value <= previous) break;
    previous = value;
    last_good_theta = theta;
  }
  // One step of margin keeps the Newton iteration away from the fold's zero derivative.
  limitFieldAngle(std::max(0.0, last_good_theta - theta_cap / steps));
}

void LensDistortion::limitFieldAngle(double max_theta_rad) {
  if (!(max_theta_rad < max_theta_rad_)) return;
  max_theta_rad_ = std::max(0.0, max_theta_rad);
  max_radial_arg_ = model_ == DistortionModel::kFisheye ? max_theta_rad_ : std::tan(max_theta_rad_);
  max_r2_pinhole_ = std::tan(max_theta_rad_) * std::tan(max_theta_rad_);
}

Eigen::Vector2d LensDistortion::distortPinhole(const Eigen::Vector2d& p,
                                               Eigen::Matrix2d* jacobian) const {
  const double x = p.x(), y = p.y();
  const double r2 = x * x + y * y;
  const double p1 = k_[2], p2 = k_[3];
  // Most calibrations have k1-k3, p1, p2 only: the rational denominator and the thin-prism
  // terms are added where they are not zero.
  const double n = 1.0 + r2 * (k_[0] + r2 * (k_[1] + r2 * k_[4]));
  double d = 1.0, radial_factor = n;
  if (rational_) {
    d = 1.0 + r2 * (k_[5] + r2 * (k_[6] + r2 * k_[7]));
    radial_factor = n / d;
  }
  double xd = x * radial_factor + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x);
  double yd = y * radial_factor + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y;
  if (thin_prism_) {
    xd += k_[8] * r2;
    xd += k_[9] * r2 * r2;
    yd += k_[10] * r2;
    yd += k_[11] * r2 * r2;
  }
  if (jacobian) {
    const double dn = k_[0] + r2 * (2.0 * k_[1] + r2 * 3.0 * k_[4]);
    double dr = dn;  // d radial_factor / d r2
    if (rational_) {
      const double dd = k_[5] + r2 * (2.0 * k_[6] + r2 * 3.0 * k_[7]);
      dr = (dn * d - n * dd) / (d * d);
    }
    double j00 = radial_factor + 2.0 * x * x * dr + 2.0 * p1 * y + 6.0 * p2 * x;
    double j01 = 2.0 * x * y * dr + 2.0 * p1 * x + 2.0 * p2 * y;
    double j10 = j01;
    double j11 = radial_factor + 2.0 * y * y * dr + 6.0 * p1 * y + 2.0 * p2 * x;
    if (thin_prism_) {
      const double prism_x = k_[8] + 2.0 * k_[9] * r2, prism_y = k_[10] + 2.0 * k_[11] * r2;
      j00 += 2.0 * x * prism_x;
      j01 += 2.0 * y * prism_x;
      j10 += 2.0 * x * prism_y;
      j11 += 2.0 * y * prism_y;
    }
    *jacobian << j00, j01, j10, j11;
  }
  return {xd, yd};
}

std::optional<Eigen::Vector2d> LensDistortion::distort(const Eigen::Vector3d& ray) const {
  if (!std::isfinite(ray.x()) || !std::isfinite(ray.y()) || !std::isfinite(ray.z()) ||
      ray.z() <= 0.0) {
    return std::nullopt;
  }
  if (model_ == DistortionModel::kPinhole) {
    const Eigen::Vector2d p(ray.x() / ray.z(), ray.y() / ray.z());
    if (p.squaredNorm() > max_r2_pinhole_) return std::nullopt;
    return distortPinhole(p);
  }
  const double rho = std::hypot(ray.x(), ray.y());
  const double theta = std::atan2(rho, ray.z());
  if (theta > max_theta_rad_) return std::nullopt;
  if (rho < 1e-300) return Eigen::Vector2d(0.0, 0.0);
  const double scale = radialFisheye(theta) / rho;
  return Eigen::Vector2d(ray.x() * scale, ray.y() * scale);
}

double LensDistortion::invertRadial(double target) const {
  // Safeguarded Newton on a monotonic function: bisection whenever a step leaves the bracket.
  double lo = 0.0, hi = max_radial_arg_;
  double x = std::clamp(target, lo, hi);
  for (int i = 0; i < 100; ++i) {
    const double f = radial(x) - target;
    if (std::abs(f) < 1e-15 * (1.0 + target)) break;
    (f > 0.0 ? hi : lo) = x;
    const double derivative = radialDerivative(x);
    double next = derivative > 0.0 ? x - f / derivative : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == x) break;
    x = next;
  }
  return x;
}

std::optional<Eigen::Vector3d> LensDistortion::undistortFisheye(const Eigen::Vector2d& d) const {
  const double theta_d = d.norm();
  if (theta_d > radialFisheye(max_theta_rad_)) return std::nullopt;
  if (theta_d < 1e-300) return Eigen::Vector3d(0.0, 0.0, 1.0);
  const double theta = invertRadial(theta_d);
  if (std::abs(radialFisheye(theta) - theta_d) > kNewtonTolerance) return std::nullopt;
  const double s = std::sin(theta) / theta_d;
  return Eigen::Vector3d(d.x() * s, d.y() * s, std::cos(theta));
}

std::optional<Eigen::Vector2d> LensDistortion::newtonPinhole(const Eigen::Vector2d& d,
                                                             Eigen::Vector2d p) const {
  // Newton with the analytic Jacobian; a step that does not reduce the residual is halved.
  Eigen::Matrix2d jacobian;
  Eigen::Vector2d residual = distortPinhole(p, &jacobian) - d;
  for (int i = 0; i < 30 && residual.norm() > kNewtonTolerance; ++i) {
    const double det = jacobian.determinant();
    if (!std::isfinite(det) || std::abs(det) < 1e-12) return std::nullopt;
    const Eigen::Vector2d delta = jacobian.inverse() * residual;
    double scale = 1.0;
    Eigen::Matrix2d next_jacobian;
    Eigen::Vector2d next = p - delta;
    Eigen::Vector2d next_residual = distortPinhole(next, &next_jacobian) - d;
    while (scale > 1e-4 && !(isFinite(next_residual) && next_residual.norm() < residual.norm())) {
      scale *= 0.5;
      next = p - scale * delta;
      next_residual = distortPinhole(next, &next_jacobian) - d;
    }
    if (!isFinite(next_residual) || next_residual.norm() >= residual.norm()) break;
    p = next;
    residual = next_residual;
    jacobian = next_jacobian;
  }
  if (!isFinite(residual) || residual.norm() > 100.0 * kNewtonTolerance) return std::nullopt;
  return p;
}

std::optional<Eigen::Vector3d> LensDistortion::undistortPinhole(const Eigen::Vector2d& d) const {
  // Mild distortion converges from the distorted point itself in a few steps; strong distortion
  // may need the purely radial inverse as the start.
  auto solution = newtonPinhole(d, d);
  if (!solution || solution->squaredNorm() > max_r2_pinhole_) {
    const double r_d = d.norm();
    solution = newtonPinhole(d, r_d > 0.0 ? Eigen::Vector2d(d * (invertRadial(r_d) / r_d)) : d);
  }
  if (!solution || solution->squaredNorm() > max_r2_pinhole_) return std::nullopt;
  return Eigen::Vector3d(solution->x(), solution->y(), 1.0).normalized();
}

std::optional<Eigen::Vector3d> LensDistortion::undistort(const Eigen::Vector2d& distorted) const {
  if (!isFinite(distorted)) return std::nullopt;
  return model_ == DistortionModel::kFisheye ? undistortFisheye(distorted)
                                             : undistortPinhole(distorted);
}

}  // namespace houghloc
