#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "field_models/pose3.h"
#include "vision/lens_distortion.h"

namespace houghloc {

/// Intrinsics as in camera.yaml (DESIGN §5.1): OpenCV's pinhole model (distortion k1, k2, p1, p2
/// [, k3 [, k4, k5, k6 [, s1..s4 [, tau_x = tau_y = 0]]]]) or its fisheye model (k1..k4).
/// Like cv::projectPoints, the model uses fx, fy, cx, cy and ignores the skew camera_matrix(0, 1).
struct CameraIntrinsics {
  int image_width = 640;   ///< px
  int image_height = 480;  ///< px
  cv::Matx33d camera_matrix = cv::Matx33d::eye();
  std::vector<double> distortion;  ///< OpenCV order; empty = none
  DistortionModel model = DistortionModel::kPinhole;
};

/// Reads camera.yaml (OpenCV FileStorage: image_width, image_height, camera_matrix,
/// distortion_coefficients, optional model: pinhole|fisheye). Throws std::runtime_error naming
/// the file and the key at fault (missing, wrong type, non-positive size or focal length,
/// distortion count the model does not define, unknown model).
CameraIntrinsics loadCameraYaml(const std::string& path);
/// Writes camera.yaml with full double precision; throws std::runtime_error naming the file when
/// it cannot be written.
void saveCameraYaml(const std::string& path, const CameraIntrinsics& intrinsics);
/// Throws std::invalid_argument describing the first problem (used by load, save and CameraModel).
void validateCameraIntrinsics(const CameraIntrinsics& intrinsics);

struct CameraModelConfig {
  double max_ground_range_m = 12.0;  ///< pixelToGround() rejects points farther than this
  double min_depression_rad = 0.02;  ///< rays flatter than this below the horizon are rejected
  /// Rays more than this beyond the image corners' angle from the optical axis are rejected by
  /// project() and pixelRay(): the lens model is only calibrated over the image.
  double field_of_view_margin_rad = 0.26;
};

/// A calibrated camera mounted on the robot (DESIGN §3). Projects robot-frame points into the
/// distorted image and back-projects pixels onto the ground plane z = 0. The OpenCV optical frame
/// is used only inside this class.
class CameraModel {
 public:
  CameraModel() = default;
  /// Throws std::invalid_argument for invalid intrinsics (validateCameraIntrinsics).
  CameraModel(const CameraIntrinsics& intrinsics, const Pose3& robot_T_camera,
              const CameraModelConfig& config = {});

  /// Changes the extrinsics (head motion) and recomputes the horizon.
  void setPose(const Pose3& robot_T_camera);

  const CameraIntrinsics& intrinsics() const { return intrinsics_; }
  const Pose3& pose() const { return robot_T_camera_; }
  const CameraModelConfig& config() const { return config_; }
  int width() const { return intrinsics_.image_width; }
  int height() const { return intrinsics_.image_height; }
  /// True for 0 <= u <= width - 1 and 0 <= v <= height - 1 (pixel centres at integers), so
  /// rounding or bilinear sampling stays inside the image.
  bool inImage(const Eigen::Vector2d& pixel) const;

  /// Pixel (u, v) of a robot-frame point in the distorted image; none when the point is behind
  /// the camera (or outside the fisheye model's valid field of view). The pixel may lie outside
  /// the image: check inImage().
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& p_robot) const;

  /// Unit viewing ray of a distorted pixel, in the robot frame (undistortion to 0.01 px; in
  /// practice ~1e-9 px). All components NaN when the pixel is not finite or lies outside the
  /// lens model's valid field of view (LensDistortion::maxFieldAngle()).
  Eigen::Vector3d pixelRay(double u, double v) const;

  /// Ground point (z = 0, robot frame) seen at a distorted pixel; none above the horizon, at
  /// grazing angles (config.min_depression_rad) or beyond config.max_ground_range_m.
  std::optional<Eigen::Vector2d> pixelToGround(double u, double v) const;

  /// Image row of the horizon (the ground plane's vanishing curve) in each column; rows below it
  /// (larger v) see the ground. Size width(); values may lie outside [0, height). A column the
  /// horizon does not cross within the lens model's valid field of view holds -infinity when
  /// it sees the ground throughout and +infinity when it sees none.
  const std::vector<double>& horizonRows() const { return horizon_rows_; }

  /// Expected pixel extent of a ground line of width line_width_m seen at pixel (u, v): x = its
  /// extent along the image row (horizontal scanline), y = along the column (vertical scanline),
  /// for a line crossing the scanline at right angles on the ground. None above the horizon.
  std::optional<Eigen::Vector2d> expectedLineWidthPx(double u, double v, double line_width_m) const;

 private:
  void computeHorizon();
  /// Narrows the lens model's valid cone to the image plus config_.field_of_view_margin_rad.
  void limitFieldOfView();
  /// Ray-plane intersection without the range and depression limits of pixelToGround().
  std::optional<Eigen::Vector3d> groundHit(double u, double v) const;

  CameraIntrinsics intrinsics_;
  LensDistortion lens_;
  /// Rotation from the OpenCV optical frame to the robot frame (robot_R_camera * camera_R_optical).
  Eigen::Matrix3d robot_R_optical_ = Eigen::Matrix3d::Identity();
  Pose3 robot_T_camera_;
  CameraModelConfig config_;
  std::vector<double> horizon_rows_;
};

}  // namespace houghloc
