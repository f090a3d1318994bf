#include "vision/image_conversion.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <stdexcept>

namespace houghloc {
namespace {

TEST(ImageConversion, YuyvRoundTripKeepsColours) {
  cv::Mat bgr(8, 16, CV_8UC3);
  cv::RNG rng(3);
  // Pairs of equal pixels, so 4:2:2 chroma subsampling loses nothing.
  for (int r = 0; r < bgr.rows; ++r) {
    for (int c = 0; c < bgr.cols; c += 2) {
      const cv::Vec3b colour(rng.uniform(20, 235), rng.uniform(20, 235), rng.uniform(20, 235));
      bgr.at<cv::Vec3b>(r, c) = bgr.at<cv::Vec3b>(r, c + 1) = colour;
    }
  }
  const cv::Mat yuyv = bgrToYuyv(bgr);
  ASSERT_EQ(yuyv.type(), CV_8UC2);
  const cv::Mat back = yuyvToBgr(yuyv);
  ASSERT_EQ(back.size(), bgr.size());
  EXPECT_LE(cv::norm(back, bgr, cv::NORM_INF), 3.0);
  EXPECT_EQ(pixelFormatOf(yuyv), PixelFormat::kYuyv);
  EXPECT_EQ(pixelFormatOf(bgr), PixelFormat::kBgr8);
}

TEST(ImageConversion, RejectsOtherTypes) {
  EXPECT_THROW(pixelFormatOf(cv::Mat(4, 4, CV_8UC1)), std::invalid_argument);
  EXPECT_THROW(yuyvToBgr(cv::Mat(4, 5, CV_8UC2)), std::invalid_argument);
  cv::Mat buffer;
  EXPECT_THROW(toBgr(cv::Mat(4, 4, CV_32FC3), buffer), std::invalid_argument);
  EXPECT_THROW(toBgr(cv::Mat(4, 5, CV_8UC2), buffer), std::invalid_argument);
}

TEST(ImageConversion, ToBgrConvertsYuyvIntoTheSameBufferAndPassesBgrThrough) {
  cv::Mat bgr(48, 64, CV_8UC3);
  cv::randu(bgr, cv::Scalar::all(0), cv::Scalar::all(255));
  const cv::Mat yuyv = bgrToYuyv(bgr);
  cv::Mat buffer;
  const cv::Mat first = toBgr(yuyv, buffer);
  const uchar* memory = buffer.data;
  EXPECT_EQ(cv::norm(first, yuyvToBgr(yuyv), cv::NORM_INF), 0.0);
  const cv::Mat second = toBgr(bgrToYuyv(255 - bgr), buffer);
  EXPECT_EQ(second.data, memory);  // reused, not reallocated
  EXPECT_EQ(cv::norm(second, yuyvToBgr(bgrToYuyv(255 - bgr)), cv::NORM_INF), 0.0);
  EXPECT_EQ(toBgr(bgr, buffer).data, bgr.data);  // BGR8: the image itself
}

}  // namespace
}  // namespace houghloc
