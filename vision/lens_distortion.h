#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace houghloc {

enum class DistortionModel { kPinhole, kFisheye };

/// OpenCV's lens distortion models on normalized image coordinates of the optical frame
/// (x right, y down, z forward), used by CameraModel:
/// - pinhole: k1, k2, p1, p2 [, k3 [, k4, k5, k6 [, s1, s2, s3, s4 [, tau_x, tau_y]]]] as in
///   cv::projectPoints (the tilted-sensor terms tau must be zero);
/// - fisheye: k1..k4 as in cv::fisheye::projectPoints (theta_d = theta (1 + k1 theta^2 + ...)).
/// Both are only invertible where the radial mapping is monotonic; that cone (maxFieldAngle())
/// is the model's valid field of view and everything outside it is rejected rather than
/// mapped to a wrong, folded-over pixel.
class LensDistortion {
 public:
  LensDistortion() = default;
  /// Throws std::invalid_argument for coefficient counts OpenCV does not define for the model,
  /// non-finite coefficients or non-zero tilt terms.
  LensDistortion(DistortionModel model, const std::vector<double>& coefficients);

  /// Distorted normalized image point (x_d, y_d) of a direction in the optical frame; none when
  /// the direction is behind the camera or outside the valid field of view.
  std::optional<Eigen::Vector2d> distort(const Eigen::Vector3d& ray_optical) const;

  /// Unit direction in the optical frame of a distorted normalized image point; none outside the
  /// valid field of view or when the Newton iteration does not converge to 1e-12.
  std::optional<Eigen::Vector3d> undistort(const Eigen::Vector2d& distorted) const;

  /// Largest angle between a ray and the optical axis the model accepts, rad.
  double maxFieldAngle() const { return max_theta_rad_; }

  /// Narrows the valid cone to max_theta_rad (never widens it): a lens calibrated over the
  /// image says nothing about rays far outside it.
  void limitFieldAngle(double max_theta_rad);

 private:
  /// OpenCV's pinhole distortion of a normalized point; `jacobian` (optional) receives its
  /// derivative for Newton's method.
  Eigen::Vector2d distortPinhole(const Eigen::Vector2d& p,
                                 Eigen::Matrix2d* jacobian = nullptr) const;
  /// r (1 + k1 r^2 + ...) / (1 + k4 r^2 + ...) without tangential or prism terms.
  double radialPinhole(double r) const;
  /// theta (1 + k1 theta^2 + k2 theta^4 + k3 theta^6 + k4 theta^8).
  double radialFisheye(double theta) const;
  /// radialPinhole(r = tan theta) or radialFisheye(theta), by model.
  double radial(double x) const;
  double radialDerivative(double x) const;
  /// Undistorted point of the distorted point d by Newton from p on the full pinhole model; none
  /// when it does not converge.
  std::optional<Eigen::Vector2d> newtonPinhole(const Eigen::Vector2d& d, Eigen::Vector2d p) const;
  void computeValidFieldAngle();
  std::optional<Eigen::Vector3d> undistortPinhole(const Eigen::Vector2d& distorted) const;
  std::optional<Eigen::Vector3d> undistortFisheye(const Eigen::Vector2d& distorted) const;
  /// Solves radial(x) = target for x in [0, max_radial_arg_] (radial() is monotonic there).
  double invertRadial(double target) const;

  DistortionModel model_ = DistortionModel::kPinhole;
  /// Pinhole: k1, k2, p1, p2, k3, k4, k5, k6, s1, s2, s3, s4 (zero-padded); fisheye: k1..k4.
  double k_[12] = {};
  /// Whether the rational denominator (k4-k6) and the thin prism (s1-s4) have a non-zero
  /// coefficient; distortPinhole() leaves out the terms that are zero (most calibrations).
  bool rational_ = false, thin_prism_ = false;
  double max_theta_rad_ = 1.5533;  ///< 89 deg until computeValidFieldAngle()
  /// Upper end of radial()'s monotonic argument range: r = tan(theta) (pinhole) or theta.
  double max_radial_arg_ = 57.0;
  double max_r2_pinhole_ = 57.0 * 57.0;  ///< max_radial_arg_^2, for the pinhole cone test
};

}  // namespace houghloc
