#include "vision_baseline.h"

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace houghloc {

OpenCvLineBaseline::OpenCvLineBaseline(const CameraIntrinsics& intrinsics)
    : intrinsics_(intrinsics) {
  const cv::Size size(intrinsics.image_width, intrinsics.image_height);
  const cv::Mat k(intrinsics.camera_matrix);
  if (intrinsics.model == DistortionModel::kFisheye) {
    cv::fisheye::initUndistortRectifyMap(k, intrinsics.distortion, cv::Mat::eye(3, 3, CV_64F), k,
                                         size, CV_32FC1, map_x_, map_y_);
  } else {
    cv::initUndistortRectifyMap(k, intrinsics.distortion, cv::Mat(), k, size, CV_32FC1, map_x_,
                                map_y_);
  }
}

GroundPoints OpenCvLineBaseline::process(const cv::Mat& bgr, const Pose3& robot_T_camera) {
  cv::Mat undistorted, hsv, white, green, edges;
  cv::remap(bgr, undistorted, map_x_, map_y_, cv::INTER_LINEAR);  // full-image undistort
  cv::cvtColor(undistorted, hsv, cv::COLOR_BGR2HSV);
  cv::inRange(hsv, cv::Scalar(0, 0, 150), cv::Scalar(180, 60, 255), white);
  cv::inRange(hsv, cv::Scalar(35, 60, 30), cv::Scalar(90, 255, 255), green);
  cv::dilate(green, green, cv::Mat(), {-1, -1}, 3);
  cv::bitwise_and(white, green, white);  // white next to green
  cv::Canny(white, edges, 50, 150);
  std::vector<cv::Vec4i> segments;
  cv::HoughLinesP(edges, segments, 1, CV_PI / 180, 30, 20, 5);

  GroundPoints out;
  const cv::Matx33d& k = intrinsics_.camera_matrix;
  // Undistorted pixel -> camera body ray (x forward, y left, z up) -> ground.
  const Eigen::Matrix3d rotation = robot_T_camera.rotation();
  for (const cv::Vec4i& s : segments) {
    const double length = std::hypot(s[2] - s[0], s[3] - s[1]);
    const int n = std::max(1, static_cast<int>(length / 4.0));
    for (int i = 0; i <= n; ++i) {
      const double u = s[0] + (s[2] - s[0]) * i / static_cast<double>(n);
      const double v = s[1] + (s[3] - s[1]) * i / static_cast<double>(n);
      const Eigen::Vector3d ray_camera(1.0, -(u - k(0, 2)) / k(0, 0), -(v - k(1, 2)) / k(1, 1));
      const Eigen::Vector3d ray = rotation * ray_camera;
      if (ray.z() > -1e-3) continue;
      const double t = robot_T_camera.z / -ray.z();
      GroundPoint p;
      p.p_robot = {robot_T_camera.x + t * ray.x(), robot_T_camera.y + t * ray.y()};
      if (p.p_robot.norm() > 5.0) continue;
      p.pixel = {static_cast<float>(u), static_cast<float>(v)};
      out.points.push_back(p);
    }
  }
  return out;
}

}  // namespace houghloc
