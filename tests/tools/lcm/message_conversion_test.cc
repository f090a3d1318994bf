// image_t <-> cv::Mat in each pixel format against the image it came from; odometry, camera
// pose and hints with NaN, wrong counts and unknown kinds refused.
#include "tools/lcm/message_conversion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "vision/image_conversion.h"

namespace houghloc {
namespace {

cv::Mat randomBgr(int width, int height, unsigned seed) {
  cv::theRNG().state = seed;
  cv::Mat bgr(height, width, CV_8UC3);
  cv::randu(bgr, cv::Scalar::all(0), cv::Scalar::all(255));
  return bgr;
}

TEST(MessageConversion, Bgr8IsExact) {
  const cv::Mat bgr = randomBgr(64, 48, 1);
  const image_t msg = imageToMessage(bgr, image_t::PIXEL_FORMAT_BGR8, 5, "top");
  const cv::Mat out = imageFromMessage(msg);
  ASSERT_EQ(out.type(), CV_8UC3);
  EXPECT_EQ(cv::norm(out, bgr, cv::NORM_INF), 0.0);
  EXPECT_EQ(out.data, msg.data.data());  // tight rows: a view, no copy
}

TEST(MessageConversion, YuyvKeepsTheBytesOfBgrToYuyv) {
  const cv::Mat bgr = randomBgr(64, 48, 2);
  const image_t msg = imageToMessage(bgr, image_t::PIXEL_FORMAT_YUYV, 5, "");
  EXPECT_EQ(msg.data.size(), 64u * 48u * 2u);
  const cv::Mat out = imageFromMessage(msg);
  ASSERT_EQ(out.type(), CV_8UC2);
  EXPECT_EQ(cv::norm(out, bgrToYuyv(bgr), cv::NORM_INF), 0.0);
}

TEST(MessageConversion, RowStrideWithPaddingIsHonoured) {
  const cv::Mat bgr = randomBgr(8, 4, 3);
  image_t msg = imageToMessage(bgr, image_t::PIXEL_FORMAT_BGR8, 5, "");
  // Re-pack with 8 bytes of padding per row.
  std::vector<std::uint8_t> padded;
  for (int r = 0; r < 4; ++r) {
    padded.insert(padded.end(), msg.data.begin() + r * 24, msg.data.begin() + (r + 1) * 24);
    padded.insert(padded.end(), 8, 0xAB);
  }
  msg.data = padded;
  msg.size = static_cast<std::int32_t>(padded.size());
  msg.row_stride = 32;
  const cv::Mat out = imageFromMessage(msg);
  EXPECT_EQ(cv::norm(out, bgr, cv::NORM_INF), 0.0);
  EXPECT_TRUE(out.isContinuous());  // copied tight: the vision reads rows without the padding
}

TEST(MessageConversion, MjpegDecodesCloseToTheOriginal) {
  cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(40, 160, 40));  // smooth: JPEG keeps it closely
  bgr(cv::Rect(10, 10, 40, 20)).setTo(cv::Scalar(255, 255, 255));
  const cv::Mat out = imageFromMessage(imageToMessage(bgr, image_t::PIXEL_FORMAT_MJPEG, 5, ""));
  ASSERT_EQ(out.size(), bgr.size());
  EXPECT_LT(cv::norm(out, bgr, cv::NORM_L1) / (64.0 * 48 * 3), 3.0);
}

TEST(MessageConversion, BadImagesThrow) {
  const cv::Mat bgr = randomBgr(8, 4, 4);
  image_t msg = imageToMessage(bgr, image_t::PIXEL_FORMAT_BGR8, 5, "");
  image_t short_data = msg;
  short_data.data.resize(10);
  short_data.size = 10;
  EXPECT_THROW(imageFromMessage(short_data), MessageError);
  image_t bad_format = msg;
  bad_format.pixel_format = 7;
  EXPECT_THROW(imageFromMessage(bad_format), MessageError);
  image_t odd_yuyv = imageToMessage(bgr, image_t::PIXEL_FORMAT_YUYV, 5, "");
  odd_yuyv.width = 7;
  EXPECT_THROW(imageFromMessage(odd_yuyv), MessageError);
  image_t bad_jpeg = msg;
  bad_jpeg.pixel_format = image_t::PIXEL_FORMAT_MJPEG;
  EXPECT_THROW(imageFromMessage(bad_jpeg), MessageError);
  image_t huge = msg;
  huge.height = 1 << 20;
  EXPECT_THROW(imageFromMessage(huge), MessageError);
}

TEST(MessageConversion, NonFiniteOdometryAndCameraPoseAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  odometry_t odo = odometryToMessage(1, Pose2(1.0, 2.0, 0.5));
  ASSERT_TRUE(odometryFromMessage(odo).has_value());
  EXPECT_DOUBLE_EQ(odometryFromMessage(odo)->y, 2.0);
  odo.theta = nan;
  EXPECT_FALSE(odometryFromMessage(odo).has_value());
  odo.theta = 0.0;
  odo.x = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(odometryFromMessage(odo).has_value());

  Pose3 pose;
  pose.z = 0.5;
  pose.pitch = 0.3;
  camera_pose_t cam = cameraPoseToMessage(1, "top", pose);
  ASSERT_TRUE(cameraPoseFromMessage(cam).has_value());
  EXPECT_DOUBLE_EQ(cameraPoseFromMessage(cam)->pitch, 0.3);
  cam.yaw = nan;
  EXPECT_FALSE(cameraPoseFromMessage(cam).has_value());
}

TEST(MessageConversion, HintsRoundTripAndBadHintsThrow) {
  LocalizationHint hint;
  hint.kind = HintKind::kAdd;
  hint.t_us = 77;
  GaussianPose a;
  a.mean = Pose2(-3.0, 2.0, -1.5);
  a.covariance(0, 1) = a.covariance(1, 0) = 0.002;
  hint.poses = {a, mirrored(a)};
  const LocalizationHint out = hintFromMessage(hintToMessage(hint));
  EXPECT_EQ(out.kind, HintKind::kAdd);
  EXPECT_EQ(out.t_us, 77);
  ASSERT_EQ(out.poses.size(), 2u);
  EXPECT_DOUBLE_EQ(out.poses[1].mean.x, 3.0);
  EXPECT_DOUBLE_EQ(out.poses[0].covariance(1, 0), 0.002);

  for (int kind = 0; kind <= 4; ++kind) {
    LocalizationHint h;
    h.kind = static_cast<HintKind>(kind);
    EXPECT_STREQ(hintKindName(hintFromMessage(hintToMessage(h)).kind),
                 hintKindName(static_cast<HintKind>(kind)));
  }
  localization_hint_t msg = hintToMessage(hint);
  msg.kind = 9;
  EXPECT_THROW(hintFromMessage(msg), MessageError);
  msg = hintToMessage(hint);
  msg.num_poses = 5;
  EXPECT_THROW(hintFromMessage(msg), MessageError);
  msg = hintToMessage(hint);
  msg.poses[0].covariance[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(hintFromMessage(msg), MessageError);
}

TEST(MessageConversion, EstimateToHypotheses) {
  LocalizationEstimate estimate;
  estimate.status = TrackerStatus::kAmbiguous;
  EstimateHypothesis h;
  h.pose.mean = Pose2(1.0, -2.0, 3.0);
  h.pose.covariance << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  h.pose.weight = 0.6;
  h.id = 4;
  h.age_frames = 12;
  estimate.hypotheses = {h, h};
  const pose_hypotheses_t msg = hypothesesToMessage(123, estimate);
  EXPECT_EQ(msg.utime, 123);
  EXPECT_EQ(msg.status, int{pose_hypotheses_t::AMBIGUOUS});
  ASSERT_EQ(msg.num_hypotheses, 2);
  EXPECT_EQ(msg.hypotheses[0].covariance[1], 2.0);  // row-major: (x, y)
  EXPECT_EQ(msg.hypotheses[0].covariance[3], 4.0);  // (y, x)
  EXPECT_EQ(msg.hypotheses[0].covariance[5], 6.0);  // (y, theta)
  EXPECT_EQ(msg.hypotheses[1].age, 12);
  EXPECT_EQ(msg.hypotheses[1].id, 4);
}

}  // namespace
}  // namespace houghloc
