// The vision on the three raw YUYV frames of ../shared/data/real (htwk_nao, hulks_nao; never
// copied into the repository) read in place, against the same frames' BGR8 decode in images/
// (OpenCV COLOR_YUV2BGR_YUY2): at least 99 % of either run's points within 1 px of the other's.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "field_models/standard_fields.h"
#include "tests/real/real_data.h"
#include "tests/vision/point_agreement.h"
#include "tools/recording/recording.h"
#include "vision/image_conversion.h"
#include "vision/vision_pipeline.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

struct RawFrame {
  const char* folder;
  const char* raw;    ///< 640x480 YUYV, Y0 Cb Y1 Cr, no header
  const char* image;  ///< its BGR8 decode, the frame's image in frames.csv
};

constexpr RawFrame kRawFrames[] = {
    {"htwk_nao", "raw/benchmark_image_640x480.yuyv", "images/benchmark_image_640x480.png"},
    {"hulks_nao", "raw/rome_bottom_ball_640x480.yuyv", "images/rome_bottom_ball.png"},
    {"hulks_nao", "raw/white_wall_with_a_little_desk_in_front_640x480.yuyv",
     "images/white_wall_with_a_little_desk_in_front.png"},
};

cv::Mat readYuyv(const fs::path& path, int width, int height) {
  cv::Mat yuyv(height, width, CV_8UC2);
  std::ifstream in(path, std::ios::binary);
  in.read(reinterpret_cast<char*>(yuyv.data), static_cast<std::streamsize>(yuyv.total() * 2));
  EXPECT_EQ(in.gcount(), static_cast<std::streamsize>(yuyv.total() * 2)) << path;
  EXPECT_EQ(in.peek(), std::char_traits<char>::eof()) << path << " is longer than 640x480 YUYV";
  return yuyv;
}

TEST(RealYuyv, InPlaceGivesTheBgrDecodesPoints) {
  REQUIRE_REAL_DATA();
  VisionConfig config;
  config.line_width_m = makeStandardField("spl").line_width;
  testing::PointAgreement all;
  for (const RawFrame& raw : kRawFrames) {
    const fs::path folder = fs::path(HOUGHLOC_REAL_DATA) / raw.folder;
    const Recording recording = readRecording(folder.string());
    const FrameRecord* frame = nullptr;
    for (const FrameRecord& f : recording.frames) {
      if (f.image == raw.image) frame = &f;
    }
    ASSERT_NE(frame, nullptr) << raw.image << " not in " << folder / "frames.csv";
    const cv::Mat bgr = cv::imread((folder / raw.image).string(), cv::IMREAD_COLOR);
    ASSERT_FALSE(bgr.empty()) << folder / raw.image;
    const cv::Mat yuyv = readYuyv(folder / raw.raw, bgr.cols, bgr.rows);
    // The PNG is the project's own decode of the raw frame.
    ASSERT_EQ(cv::norm(yuyvToBgr(yuyv), bgr, cv::NORM_INF), 0.0) << raw.raw;

    VisionPipeline from_yuyv(recording.intrinsicsFor(*frame), config);
    VisionPipeline from_bgr(recording.intrinsicsFor(*frame), config);
    const VisionResult a = from_yuyv.process(yuyv, frame->robot_T_camera, frame->t_us);
    const VisionResult b = from_bgr.process(bgr, frame->robot_T_camera, frame->t_us);
    testing::PointAgreement one;
    one.add(a.ground.points, b.ground.points, 1.0);
    all.add(a.ground.points, b.ground.points, 1.0);
    std::printf("%s/%s: YUYV %zu points, BGR8 %zu, %zu and %zu within 1 px of the other's\n",
                raw.folder, raw.raw, one.points_a, one.points_b, one.matched_a, one.matched_b);
  }
  std::printf("all three frames: YUYV %zu points, BGR8 %zu, share within 1 px %.4f\n", all.points_a,
              all.points_b, all.share());
  // The frame with lines (htwk benchmark image) gives points; a share over nothing proves nothing.
  EXPECT_GE(all.points_b, 20u);
  EXPECT_GE(all.share(), 0.99);
}

}  // namespace
}  // namespace houghloc
