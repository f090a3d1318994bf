#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "field_models/pose3.h"

namespace houghloc {

enum class DistortionModel { kPinhole, kFisheye };

/// Intrinsics as in camera.yaml (DESIGN §5.1): OpenCV's pinhole model (distortion k1, k2, p1, p2
/// [, k3 [, k4, k5, k6]]) or its fisheye model (k1..k4).
struct CameraIntrinsics {
  int image_width = 640;   ///< px
  int image_height = 480;  ///< px
  cv::Matx33d camera_matrix = cv::Matx33d::eye();
  std::vector<double> distortion;  ///< OpenCV order; empty = none
  DistortionModel model = DistortionModel::kPinhole;
};

/// Reads camera.yaml (OpenCV FileStorage: image_width, image_height, camera_matrix,
/// distortion_coefficients, optional model: pinhole|fisheye). Throws std::runtime_error naming
/// the file and the key at fault.
CameraIntrinsics loadCameraYaml(const std::string& path);
void saveCameraYaml(const std::string& path, const CameraIntrinsics& intrinsics);

struct CameraModelConfig {
  double max_ground_range_m = 12.0;  ///< pixelToGround() rejects points farther than this
  double min_depression_rad = 0.02;  ///< rays flatter than this below the horizon are rejected
};

/// A calibrated camera mounted on the robot (DESIGN §3). Projects robot-frame points into the
/// distorted image and back-projects pixels onto the ground plane z = 0. The OpenCV optical frame
/// is used only inside this class.
class CameraModel {
 public:
  CameraModel() = default;
  CameraModel(const CameraIntrinsics& intrinsics, const Pose3& robot_T_camera,
              const CameraModelConfig& config = {});

  /// Changes the extrinsics (head motion) and recomputes the horizon.
  void setPose(const Pose3& robot_T_camera);

  const CameraIntrinsics& intrinsics() const { return intrinsics_; }
  const Pose3& pose() const { return robot_T_camera_; }
  const CameraModelConfig& config() const { return config_; }
  int width() const { return intrinsics_.image_width; }
  int height() const { return intrinsics_.image_height; }
  bool inImage(const Eigen::Vector2d& pixel) const;

  /// Pixel (u, v) of a robot-frame point in the distorted image; none when the point is behind
  /// the camera (or outside the fisheye model's valid field of view). The pixel may lie outside
  /// the image: check inImage().
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& p_robot) const;

  /// Unit viewing ray of a distorted pixel, in the robot frame (undistortion to 0.01 px).
  Eigen::Vector3d pixelRay(double u, double v) const;

  /// Ground point (z = 0, robot frame) seen at a distorted pixel; none above the horizon, at
  /// grazing angles (config.min_depression_rad) or beyond config.max_ground_range_m.
  std::optional<Eigen::Vector2d> pixelToGround(double u, double v) const;

  /// Image row of the horizon (the ground plane's vanishing curve) in each column; rows below it
  /// (larger v) see the ground. Size width(); values may lie outside [0, height).
  const std::vector<double>& horizonRows() const { return horizon_rows_; }

  /// Expected pixel extent of a ground line of width line_width_m seen at pixel (u, v): x = its
  /// extent along the image row (horizontal scanline), y = along the column (vertical scanline),
  /// for a line crossing the scanline at right angles on the ground. None above the horizon.
  std::optional<Eigen::Vector2d> expectedLineWidthPx(double u, double v,
                                                     double line_width_m) const;

 private:
  void computeHorizon();

  CameraIntrinsics intrinsics_;
  Pose3 robot_T_camera_;
  CameraModelConfig config_;
  std::vector<double> horizon_rows_;
};

}  // namespace houghloc
