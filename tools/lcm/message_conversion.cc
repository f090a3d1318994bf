#include "tools/lcm/message_conversion.h"

#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "vision/image_conversion.h"

namespace houghloc {
namespace {

void copyCovariance(const Eigen::Matrix3d& from, double* to) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) to[3 * r + c] = from(r, c);  // row-major over (x, y, theta)
}

Eigen::Matrix3d covarianceFrom(const double* from) {
  Eigen::Matrix3d out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out(r, c) = from[3 * r + c];
  return out;
}

pose_hypothesis_t hypothesisToMessage(const GaussianPose& pose, int id, int age) {
  pose_hypothesis_t out;
  out.id = id;
  out.x = pose.mean.x;
  out.y = pose.mean.y;
  out.theta = pose.mean.theta;
  copyCovariance(pose.covariance, out.covariance);
  out.weight = pose.weight;
  out.age = age;
  return out;
}

// Rows of bytes_per_pixel * width bytes, row_stride apart, into a tight Mat of `type`.
cv::Mat rowsFromMessage(const image_t& msg, int type, int bytes_per_pixel) {
  const std::int64_t row_bytes = static_cast<std::int64_t>(msg.width) * bytes_per_pixel;
  if (msg.row_stride < row_bytes)
    throw MessageError("image_t row_stride " + std::to_string(msg.row_stride) + " < " +
                       std::to_string(row_bytes) + " bytes of a row");
  const std::int64_t needed =
      static_cast<std::int64_t>(msg.row_stride) * (msg.height - 1) + row_bytes;
  if (static_cast<std::int64_t>(msg.data.size()) < needed)
    throw MessageError("image_t holds " + std::to_string(msg.data.size()) + " bytes, " +
                       std::to_string(msg.width) + "x" + std::to_string(msg.height) + " needs " +
                       std::to_string(needed));
  const cv::Mat view(msg.height, msg.width, type, const_cast<std::uint8_t*>(msg.data.data()),
                     static_cast<std::size_t>(msg.row_stride));
  // Tight rows (every camera's) go to the vision without a copy; padded rows are copied tight.
  return msg.row_stride == row_bytes ? view : view.clone();
}

}  // namespace

cv::Mat imageFromMessage(const image_t& msg) {
  if (msg.size != static_cast<std::int32_t>(msg.data.size()))
    throw MessageError("image_t size field differs from its data");
  if (msg.pixel_format == image_t::PIXEL_FORMAT_MJPEG) {
    // OpenCV asserts (cv::Exception) on empty input and on some corrupt streams instead of
    // returning an empty image; a message must never end the node (fuzz target node).
    cv::Mat bgr;
    try {
      if (!msg.data.empty()) bgr = cv::imdecode(msg.data, cv::IMREAD_COLOR);
    } catch (const cv::Exception&) {
      bgr.release();
    }
    if (bgr.empty()) throw MessageError("image_t MJPEG data does not decode");
    return bgr;
  }
  if (msg.width <= 0 || msg.height <= 0 || msg.width > 16384 || msg.height > 16384)
    throw MessageError("image_t size " + std::to_string(msg.width) + "x" +
                       std::to_string(msg.height) + " out of range");
  if (msg.pixel_format == image_t::PIXEL_FORMAT_BGR8) return rowsFromMessage(msg, CV_8UC3, 3);
  if (msg.pixel_format == image_t::PIXEL_FORMAT_YUYV) {
    if (msg.width % 2 != 0) throw MessageError("image_t YUYV width is odd");
    return rowsFromMessage(msg, CV_8UC2, 2);
  }
  throw MessageError("image_t pixel_format " + std::to_string(int{msg.pixel_format}) +
                     " unknown (0 BGR8, 1 YUYV, 2 MJPEG)");
}

image_t imageToMessage(const cv::Mat& bgr, std::int8_t pixel_format, std::int64_t utime,
                       const std::string& camera_id) {
  image_t msg;
  msg.utime = utime;
  msg.camera_id = camera_id;
  msg.width = bgr.cols;
  msg.height = bgr.rows;
  msg.pixel_format = pixel_format;
  cv::Mat pixels;
  if (pixel_format == image_t::PIXEL_FORMAT_MJPEG) {
    cv::imencode(".jpg", bgr, msg.data, {cv::IMWRITE_JPEG_QUALITY, 90});
    msg.row_stride = 0;
  } else {
    pixels = pixel_format == image_t::PIXEL_FORMAT_YUYV ? bgrToYuyv(bgr) : bgr.clone();
    msg.row_stride = static_cast<std::int32_t>(pixels.cols * pixels.elemSize());
    msg.data.assign(pixels.datastart, pixels.dataend);
  }
  msg.size = static_cast<std::int32_t>(msg.data.size());
  return msg;
}

std::optional<Pose2> odometryFromMessage(const odometry_t& msg) {
  // Pose2's constructor wraps theta; check the raw values first.
  if (!std::isfinite(msg.x) || !std::isfinite(msg.y) || !std::isfinite(msg.theta))
    return std::nullopt;
  return Pose2(msg.x, msg.y, msg.theta);
}

odometry_t odometryToMessage(std::int64_t utime, const Pose2& odometry) {
  odometry_t msg{};
  msg.utime = utime;
  msg.x = odometry.x;
  msg.y = odometry.y;
  msg.theta = odometry.theta;
  return msg;  // covariance all zero: unknown
}

std::optional<Pose3> cameraPoseFromMessage(const camera_pose_t& msg) {
  Pose3 pose;
  pose.x = msg.x;
  pose.y = msg.y;
  pose.z = msg.z;
  pose.roll = msg.roll;
  pose.pitch = msg.pitch;
  pose.yaw = msg.yaw;
  if (!pose.isFinite()) return std::nullopt;
  return pose;
}

camera_pose_t cameraPoseToMessage(std::int64_t utime, const std::string& camera_id,
                                  const Pose3& robot_T_camera) {
  camera_pose_t msg;
  msg.utime = utime;
  msg.camera_id = camera_id;
  msg.x = robot_T_camera.x;
  msg.y = robot_T_camera.y;
  msg.z = robot_T_camera.z;
  msg.roll = robot_T_camera.roll;
  msg.pitch = robot_T_camera.pitch;
  msg.yaw = robot_T_camera.yaw;
  return msg;
}

LocalizationHint hintFromMessage(const localization_hint_t& msg) {
  if (msg.kind < localization_hint_t::UNKNOWN || msg.kind > localization_hint_t::MIRROR)
    throw MessageError("localization_hint_t kind " + std::to_string(int{msg.kind}) + " unknown");
  if (msg.num_poses != static_cast<std::int32_t>(msg.poses.size()))
    throw MessageError("localization_hint_t num_poses differs from its poses");
  LocalizationHint hint;
  hint.kind = static_cast<HintKind>(msg.kind);  // same order as HintKind
  hint.t_us = msg.utime;
  for (const pose_hypothesis_t& p : msg.poses) {
    GaussianPose pose;
    if (!std::isfinite(p.theta)) throw MessageError("localization_hint_t pose not finite");
    pose.mean = Pose2(p.x, p.y, p.theta);
    pose.covariance = covarianceFrom(p.covariance);
    pose.weight = p.weight;
    if (!pose.isFinite()) throw MessageError("localization_hint_t pose not finite");
    hint.poses.push_back(pose);
  }
  return hint;
}

localization_hint_t hintToMessage(const LocalizationHint& hint) {
  localization_hint_t msg;
  msg.utime = hint.t_us;
  msg.kind = static_cast<std::int8_t>(hint.kind);
  for (std::size_t i = 0; i < hint.poses.size(); ++i)
    msg.poses.push_back(hypothesisToMessage(hint.poses[i], static_cast<int>(i), 0));
  msg.num_poses = static_cast<std::int32_t>(msg.poses.size());
  return msg;
}

std::int8_t statusToMessage(LocalizationStatus status) {
  switch (status) {
    case TrackerStatus::kInitializing:
      return pose_hypotheses_t::INITIALIZING;
    case TrackerStatus::kTracking:
      return pose_hypotheses_t::TRACKING;
    case TrackerStatus::kAmbiguous:
      return pose_hypotheses_t::AMBIGUOUS;
    case TrackerStatus::kLost:
      return pose_hypotheses_t::LOST;
  }
  return pose_hypotheses_t::LOST;
}

pose_hypotheses_t hypothesesToMessage(std::int64_t utime, const LocalizationEstimate& estimate) {
  pose_hypotheses_t msg;
  msg.utime = utime;
  msg.status = statusToMessage(estimate.status);
  for (const EstimateHypothesis& h : estimate.hypotheses)
    msg.hypotheses.push_back(hypothesisToMessage(h.pose, h.id, h.age_frames));
  msg.num_hypotheses = static_cast<std::int32_t>(msg.hypotheses.size());
  return msg;
}

}  // namespace houghloc
