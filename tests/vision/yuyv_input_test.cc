// YUYV input read in place (pixel_access.h) against the same frame decoded to BGR8 first with
// OpenCV (yuyvToBgr): the pixels the stages see and the points they find must be the same.
#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/core.hpp>
#include <stdexcept>

#include "point_agreement.h"
#include "vision/image_conversion.h"
#include "vision/pixel_access.h"
#include "vision/vision_pipeline.h"
#include "vision_test_views.h"

namespace houghloc {
namespace {

bool sameBytes(const BgrBytes& a, const uchar* b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

TEST(YuyvPixels, DecodesEveryYCbCrLikeOpenCv) {
  // Row Cb + 256 Cr holds every luma once: pixel pair k has Y0 = 2k, Y1 = 2k + 1.
  cv::Mat yuyv(256 * 256, 256, CV_8UC2);
  for (int row = 0; row < yuyv.rows; ++row) {
    uchar* p = yuyv.ptr<uchar>(row);
    for (int k = 0; k < 128; ++k, p += 4) {
      p[0] = static_cast<uchar>(2 * k);
      p[1] = static_cast<uchar>(row & 255);
      p[2] = static_cast<uchar>(2 * k + 1);
      p[3] = static_cast<uchar>(row >> 8);
    }
  }
  const cv::Mat bgr = yuyvToBgr(yuyv);
  const YuyvPixels pixels(yuyv);
  long mismatches = 0;
  for (int v = 0; v < yuyv.rows; ++v) {
    for (int u = 0; u < yuyv.cols; ++u) {
      mismatches += !sameBytes(pixels.at(u, v), bgr.ptr<uchar>(v) + 3 * u);
    }
  }
  EXPECT_EQ(mismatches, 0) << "of " << yuyv.total() << " pixels";
  // Pixel k of a run against pixel (u, v) of the BGR decode: bytes and luma.
  const auto differs = [&](const DecodedRun& run, int k, int u, int v) {
    const uchar* expected = bgr.ptr<uchar>(v) + 3 * u;
    const uchar* got = run.at(k);
    return !sameBytes({got[0], got[1], got[2]}, expected) ||
           run.luma(k) != FieldColor::luma(expected);
  };
  // Column u holds every (Cb, Cr) with Y = u: the vectorised column decoding, all 2^24 too.
  RunBuffer buffer;
  long column_mismatches = 0;
  for (int u = 0; u < yuyv.cols; ++u) {
    const DecodedRun column = pixels.columnRun(u, 0, yuyv.rows, &buffer);
    for (int v = 0; v < yuyv.rows; ++v) column_mismatches += differs(column, v, u, v);
  }
  EXPECT_EQ(column_mismatches, 0) << "of " << yuyv.total() << " pixels";
  // Row Cb + 256 Cr as one run (OpenCV's row decoding and the vectorised luma), all 2^24 too.
  long row_mismatches = 0;
  for (int v = 0; v < yuyv.rows; ++v) {
    const DecodedRun row = pixels.rowRun(0, v, yuyv.cols, &buffer);
    for (int u = 0; u < yuyv.cols; ++u) row_mismatches += differs(row, u, u, v);
  }
  EXPECT_EQ(row_mismatches, 0) << "of " << yuyv.total() << " pixels";
}

TEST(YuyvPixels, RunsHoldTheDecodedPixels) {
  cv::Mat yuyv(24, 64, CV_8UC2);
  cv::RNG(7).fill(yuyv, cv::RNG::UNIFORM, 0, 256);
  const cv::Mat bgr = yuyvToBgr(yuyv);
  const YuyvPixels pixels(yuyv);
  RunBuffer buffer;
  // Odd and even starts: a run may begin with either pixel of a pair. Rows of 37 px: two
  // 16-pixel blocks of the vectorised decoding and a tail.
  for (const int start : {0, 1, 6, 13}) {
    const int row_n = 37;
    const DecodedRun row = pixels.rowRun(start, 5, row_n, &buffer);
    for (int k = 0; k < row_n; ++k) {
      const uchar* expected = bgr.ptr<uchar>(5) + 3 * (start + k);
      EXPECT_TRUE(sameBytes({row.at(k)[0], row.at(k)[1], row.at(k)[2]}, expected))
          << "row run from u " << start << ", pixel " << k;
      EXPECT_EQ(row.luma(k), FieldColor::luma(expected));
    }
    const int column_n = 21;  // one 16-pixel block of the vectorised decoding and a tail
    const DecodedRun column = pixels.columnRun(start, 3, column_n, &buffer);
    for (int k = 0; k < column_n; ++k) {
      const uchar* expected = bgr.ptr<uchar>(3 + k) + 3 * start;
      EXPECT_TRUE(sameBytes({column.at(k)[0], column.at(k)[1], column.at(k)[2]}, expected))
          << "column run at u " << start << ", pixel " << k;
      EXPECT_EQ(column.luma(k), FieldColor::luma(expected));
    }
  }
}

TEST(YuyvPixels, RejectsOddWidthsAndOtherTypes) {
  EXPECT_THROW(YuyvPixels(cv::Mat(4, 5, CV_8UC2)), std::invalid_argument);
  EXPECT_THROW(checkPixelLayout(cv::Mat(4, 5, CV_8UC2)), std::invalid_argument);
  EXPECT_THROW(checkPixelLayout(cv::Mat(4, 6, CV_8UC1)), std::invalid_argument);
  EXPECT_NO_THROW(checkPixelLayout(cv::Mat(4, 6, CV_8UC2)));
  EXPECT_NO_THROW(checkPixelLayout(cv::Mat(4, 5, CV_8UC3)));
}

struct YuyvCase {
  const char* preset;
  const char* field;
  Pose2 pose;
};

void PrintTo(const YuyvCase& c, std::ostream* os) { *os << c.preset << "/" << c.field; }

class YuyvOnViews : public ::testing::TestWithParam<YuyvCase> {};

/// A rendered view as YUYV, run once as it is and once decoded to BGR8 first: every point of
/// either run lies within 1 px of one of the other's.
TEST_P(YuyvOnViews, GivesTheBgrDecodesPoints) {
  const YuyvCase& c = GetParam();
  testing::SyntheticStyle style;
  style.gradient = 0.3;
  style.noise_sigma = 3.0;
  const testing::TestView& view = testing::testView(c.preset, c.field, c.pose, style);
  const cv::Mat yuyv = bgrToYuyv(view.image);
  VisionConfig config;
  config.line_width_m = view.field.line_width;
  VisionPipeline from_yuyv(view.preset.intrinsics, config);
  VisionPipeline from_bgr(view.preset.intrinsics, config);
  const VisionResult a = from_yuyv.process(yuyv, view.preset.robot_T_camera);
  const VisionResult b = from_bgr.process(yuyvToBgr(yuyv), view.preset.robot_T_camera);
  testing::PointAgreement agreement;
  agreement.add(a.ground.points, b.ground.points, 1.0);
  std::printf("%s/%s: YUYV %zu points, BGR decode %zu, %.4f within 1 px\n", c.preset, c.field,
              agreement.points_a, agreement.points_b, agreement.share());
  EXPECT_GE(b.ground.points.size(), 10u);
  EXPECT_EQ(a.ground.points.size(), b.ground.points.size());
  EXPECT_EQ(agreement.share(), 1.0);
}

INSTANTIATE_TEST_SUITE_P(PresetsAndFields, YuyvOnViews,
                         ::testing::Values(YuyvCase{"nao-top", "spl", Pose2(-2.0, -1.0, 0.5)},
                                           YuyvCase{"nao-bottom", "spl", Pose2(-0.35, 0.2, 0.1)},
                                           YuyvCase{"adult", "adult", Pose2(-3.0, -1.0, 0.2)}));

}  // namespace
}  // namespace houghloc
