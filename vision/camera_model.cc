#include "vision/camera_model.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "field_models/angles.h"

namespace houghloc {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// camera_R_optical: optical (x right, y down, z forward) -> camera body (x forward, y left,
/// z up), i.e. p_cam = (z_o, -x_o, -y_o) (DESIGN §3).
Eigen::Matrix3d cameraFromOptical() {
  Eigen::Matrix3d m;
  m << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  return m;
}

bool allFinite(const Eigen::Vector3d& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

/// Angles at which computeHorizon() samples the horizontal directions: a_i = -pi + 2 pi i / n.
constexpr int kHorizonSamples = 2048;
double horizonSampleAngle(int i) { return -kPi + 2.0 * kPi * i / kHorizonSamples; }

/// (cos a_i, sin a_i) for i = 0..kHorizonSamples: the same for every pose, so computed once
/// (the sines and cosines were a third of computeHorizon()'s cost).
const std::vector<Eigen::Vector2d>& horizonSampleDirections() {
  static const std::vector<Eigen::Vector2d> directions = [] {
    std::vector<Eigen::Vector2d> out(kHorizonSamples + 1);
    for (int i = 0; i <= kHorizonSamples; ++i) {
      const double a = horizonSampleAngle(i);
      out[i] = Eigen::Vector2d(std::cos(a), std::sin(a));
    }
    return out;
  }();
  return directions;
}

}  // namespace

void validateCameraIntrinsics(const CameraIntrinsics& in) {
  if (in.image_width <= 0 || in.image_height <= 0) {
    throw std::invalid_argument("image size must be positive, got " +
                                std::to_string(in.image_width) + "x" +
                                std::to_string(in.image_height));
  }
  const cv::Matx33d& k = in.camera_matrix;
  for (int i = 0; i < 9; ++i) {
    if (!std::isfinite(k.val[i])) throw std::invalid_argument("camera_matrix is not finite");
  }
  if (!(k(0, 0) > 0.0) || !(k(1, 1) > 0.0)) {
    throw std::invalid_argument("camera_matrix focal lengths fx, fy must be positive");
  }
  if (k(1, 0) != 0.0 || k(2, 0) != 0.0 || k(2, 1) != 0.0 || k(2, 2) != 1.0) {
    throw std::invalid_argument("camera_matrix must be [fx s cx; 0 fy cy; 0 0 1]");
  }
  LensDistortion(in.model, in.distortion);  // throws for invalid coefficients
}

CameraModel::CameraModel(const CameraIntrinsics& intrinsics, const Pose3& robot_T_camera,
                         const CameraModelConfig& config)
    : intrinsics_(intrinsics), config_(config) {
  validateCameraIntrinsics(intrinsics_);
  lens_ = LensDistortion(intrinsics_.model, intrinsics_.distortion);
  limitFieldOfView();
  setPose(robot_T_camera);
}

void CameraModel::limitFieldOfView() {
  // The widest ray of the image leaves through a corner or, for unusual distortion, an edge's
  // middle; the model stays valid a margin beyond it.
  const cv::Matx33d& k = intrinsics_.camera_matrix;
  const double right = width() - 0.5, bottom = height() - 0.5;
  const double us[] = {-0.5, 0.5 * (width() - 1), right};
  const double vs[] = {-0.5, 0.5 * (height() - 1), bottom};
  double widest = 0.0;
  for (double u : us) {
    for (double v : vs) {
      const auto ray = lens_.undistort({(u - k(0, 2)) / k(0, 0), (v - k(1, 2)) / k(1, 1)});
      if (!ray) return;  // part of the image is already outside the model's valid cone
      widest = std::max(widest, std::acos(std::clamp(ray->z(), -1.0, 1.0)));
    }
  }
  lens_.limitFieldAngle(widest + config_.field_of_view_margin_rad);
}

void CameraModel::setPose(const Pose3& robot_T_camera) {
  robot_T_camera_ = robot_T_camera;
  robot_R_optical_ = robot_T_camera_.rotation() * cameraFromOptical();
  computeHorizon();
}

bool CameraModel::inImage(const Eigen::Vector2d& pixel) const {
  return pixel.x() >= 0.0 && pixel.x() <= width() - 1.0 && pixel.y() >= 0.0 &&
         pixel.y() <= height() - 1.0;
}

std::optional<Eigen::Vector2d> CameraModel::project(const Eigen::Vector3d& p_robot) const {
  if (!allFinite(p_robot)) return std::nullopt;
  const Eigen::Vector3d p_optical =
      robot_R_optical_.transpose() * (p_robot - robot_T_camera_.translation());
  const auto normalized = lens_.distort(p_optical);
  if (!normalized) return std::nullopt;
  const cv::Matx33d& k = intrinsics_.camera_matrix;
  return Eigen::Vector2d(k(0, 0) * normalized->x() + k(0, 2), k(1, 1) * normalized->y() + k(1, 2));
}

Eigen::Vector3d CameraModel::pixelRay(double u, double v) const {
  const cv::Matx33d& k = intrinsics_.camera_matrix;
  const Eigen::Vector2d normalized((u - k(0, 2)) / k(0, 0), (v - k(1, 2)) / k(1, 1));
  const auto ray_optical = lens_.undistort(normalized);
  if (!ray_optical) return Eigen::Vector3d::Constant(kNaN);
  return robot_R_optical_ * *ray_optical;
}

std::optional<Eigen::Vector3d> CameraModel::groundHit(double u, double v) const {
  const Eigen::Vector3d origin = robot_T_camera_.translation();
  const Eigen::Vector3d ray = pixelRay(u, v);
  if (!allFinite(ray) || !allFinite(origin) || origin.z() <= 0.0 || ray.z() >= 0.0) {
    return std::nullopt;
  }
  const Eigen::Vector3d hit = origin + (-origin.z() / ray.z()) * ray;
  if (!allFinite(hit)) return std::nullopt;
  return Eigen::Vector3d(hit.x(), hit.y(), 0.0);
}

std::optional<Eigen::Vector2d> CameraModel::pixelToGround(double u, double v) const {
  const Eigen::Vector3d ray = pixelRay(u, v);
  // ray is a unit vector, so -ray.z() is the sine of the depression below the horizon.
  if (!allFinite(ray) || -ray.z() < std::sin(config_.min_depression_rad)) return std::nullopt;
  const auto hit = groundHit(u, v);
  if (!hit || hit->head<2>().norm() > config_.max_ground_range_m) return std::nullopt;
  return hit->head<2>();
}

// The horizon is where the image of the ground plane's points at infinity lies: the projections
// of the horizontal directions (cos a, sin a, 0). Sampling a and solving u(a) = column per
// column with safeguarded secant steps costs a few forward projections per column, no
// undistortion, so setPose() stays cheap enough for per-frame head motion.
void CameraModel::computeHorizon() {
  horizon_rows_.assign(width(), kNaN);
  if (!robot_T_camera_.isFinite()) {
    horizon_rows_.assign(width(), kInf);
    return;
  }
  const cv::Matx33d& k = intrinsics_.camera_matrix;
  // The pixel of the horizontal direction (cos a, sin a, 0) given as `direction`.
  auto pixelOfDirection = [&](const Eigen::Vector2d& direction) -> std::optional<Eigen::Vector2d> {
    const Eigen::Vector3d d_optical =
        robot_R_optical_.transpose() * Eigen::Vector3d(direction.x(), direction.y(), 0.0);
    const auto n = lens_.distort(d_optical);
    if (!n) return std::nullopt;
    return Eigen::Vector2d(k(0, 0) * n->x() + k(0, 2), k(1, 1) * n->y() + k(1, 2));
  };
  auto pixelOf = [&](double a) {
    return pixelOfDirection(Eigen::Vector2d(std::cos(a), std::sin(a)));
  };
  const int samples = kHorizonSamples;
  const std::vector<Eigen::Vector2d>& directions = horizonSampleDirections();
  std::vector<std::optional<Eigen::Vector2d>> pixels(samples + 1);
  for (int i = 0; i <= samples; ++i) pixels[i] = pixelOfDirection(directions[i]);
  for (int i = 0; i < samples; ++i) {
    if (!pixels[i] || !pixels[i + 1]) continue;
    const double u0 = pixels[i]->x(), u1 = pixels[i + 1]->x();
    if (!std::isfinite(u0) || !std::isfinite(u1)) continue;
    // Clamped as doubles first: a ray near the image plane projects far beyond any int.
    const double last_column = width() - 1;
    const int first =
        static_cast<int>(std::clamp(std::ceil(std::min(u0, u1)), 0.0, last_column + 1));
    const int last = static_cast<int>(std::clamp(std::floor(std::max(u0, u1)), -1.0, last_column));
    for (int column = first; column <= last; ++column) {
      if (!std::isnan(horizon_rows_[column])) continue;
      // Secant steps, kept inside the bracket [a_lo, a_hi] (bisection when they leave it).
      double a_lo = horizonSampleAngle(i), f_lo = u0 - column;
      double a_hi = horizonSampleAngle(i + 1), f_hi = u1 - column;
      double a0 = a_lo, f0 = f_lo, a1 = a_hi, f1 = f_hi;
      double v = std::abs(f_lo) < std::abs(f_hi) ? pixels[i]->y() : pixels[i + 1]->y();
      for (int iteration = 0; iteration < 40 && f_lo != 0.0 && f_hi != 0.0; ++iteration) {
        double a = a1 - f1 * (a1 - a0) / (f1 - f0);
        if (!(a > a_lo && a < a_hi)) a = 0.5 * (a_lo + a_hi);
        const auto p = pixelOf(a);
        if (!p) break;
        const double f = p->x() - column;
        v = p->y();
        if (std::abs(f) < 1e-7) break;
        ((f < 0.0) == (f_lo < 0.0) ? a_lo : a_hi) = a;
        ((f < 0.0) == (f_lo < 0.0) ? f_lo : f_hi) = f;
        a0 = a1, f0 = f1, a1 = a, f1 = f;
      }
      horizon_rows_[column] = v;
    }
  }
  // Columns the horizon misses: all ground or no ground, judged by the centre ray of the first
  // column of each run of them (one undistortion per run keeps setPose() cheap).
  double run_value = kNaN;
  for (int column = 0; column < width(); ++column) {
    if (!std::isnan(horizon_rows_[column]) && !std::isinf(horizon_rows_[column])) {
      run_value = kNaN;
      continue;
    }
    if (std::isnan(run_value)) {
      const Eigen::Vector3d ray = pixelRay(column, 0.5 * (height() - 1));
      run_value = allFinite(ray) && ray.z() < 0.0 ? -kInf : kInf;
    }
    horizon_rows_[column] = run_value;
  }
}

std::optional<Eigen::Vector2d> CameraModel::expectedLineWidthPx(double u, double v,
                                                                double line_width_m) const {
  if (!std::isfinite(line_width_m) || line_width_m < 0.0) return std::nullopt;
  const auto center = groundHit(u, v);
  if (!center) return std::nullopt;
  // Direction on the ground of the scanline through (u, v); the line crosses it at right angles,
  // so its two edges lie half a width either side of the centre along that direction.
  auto extentAlong = [&](double du, double dv) -> std::optional<double> {
    const auto ahead = groundHit(u + du, v + dv);
    const auto behind = groundHit(u - du, v - dv);
    if (!ahead || !behind) return std::nullopt;
    const Eigen::Vector3d direction = (*ahead - *behind).normalized();
    const auto edge1 = project(*center + 0.5 * line_width_m * direction);
    const auto edge2 = project(*center - 0.5 * line_width_m * direction);
    if (!edge1 || !edge2) return std::nullopt;
    return (*edge1 - *edge2).norm();
  };
  const auto along_row = extentAlong(0.5, 0.0);
  const auto along_column = extentAlong(0.0, 0.5);
  if (!along_row || !along_column) return std::nullopt;
  return Eigen::Vector2d(*along_row, *along_column);
}

}  // namespace houghloc
