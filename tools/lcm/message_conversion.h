#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <stdexcept>
#include <string>

#include "field_models/pose2.h"
#include "field_models/pose3.h"
#include "houghloc/camera_pose_t.hpp"
#include "houghloc/image_t.hpp"
#include "houghloc/localization_hint_t.hpp"
#include "houghloc/odometry_t.hpp"
#include "houghloc/pose_hypotheses_t.hpp"
#include "localization/localization_hint.h"
#include "localization/localizer.h"

namespace houghloc {

/// A message that decoded but cannot be used (wrong sizes, unknown format, NaN); what() says why.
class MessageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// image_t -> the layouts VisionPipeline accepts: BGR8 as CV_8UC3 and YUYV as CV_8UC2, in tight
/// rows (a view of msg.data when its rows are tight: valid while msg lives and its data is not
/// resized, clone() to keep it; else a copy), MJPEG decoded to BGR8. Throws MessageError on sizes
/// that do not match the data, an odd YUYV width or an undecodable JPEG.
cv::Mat imageFromMessage(const image_t& msg);

/// A BGR8 image as image_t in `pixel_format` (image_t::PIXEL_FORMAT_*); MJPEG at JPEG quality 90.
image_t imageToMessage(const cv::Mat& bgr, std::int8_t pixel_format, std::int64_t utime,
                       const std::string& camera_id);

/// Cumulative odometry; none when a value is NaN or infinite (it never reaches the filter).
std::optional<Pose2> odometryFromMessage(const odometry_t& msg);
odometry_t odometryToMessage(std::int64_t utime, const Pose2& odometry);

/// robot_T_camera; none when a value is NaN or infinite.
std::optional<Pose3> cameraPoseFromMessage(const camera_pose_t& msg);
camera_pose_t cameraPoseToMessage(std::int64_t utime, const std::string& camera_id,
                                  const Pose3& robot_T_camera);

/// Throws MessageError for an unknown kind, a pose count that differs from the array or a
/// non-finite pose or covariance.
LocalizationHint hintFromMessage(const localization_hint_t& msg);
localization_hint_t hintToMessage(const LocalizationHint& hint);

/// pose_hypotheses_t.status for a Localizer status (same names as poses.csv).
std::int8_t statusToMessage(LocalizationStatus status);
/// The estimate as pose_hypotheses_t with the image's utime.
pose_hypotheses_t hypothesesToMessage(std::int64_t utime, const LocalizationEstimate& estimate);

}  // namespace houghloc
