#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "vision/vision_pipeline.h"
#include "vision_test_views.h"

namespace houghloc {
namespace {

testing::VisionRun runWithBlendWidth(const testing::TestView& view, const cv::Mat& image,
                                     double max_blend_width_px) {
  VisionConfig config;
  config.spots.max_blend_width_px = max_blend_width_px;
  return testing::runVision(view, image, config);  // far: 3 m or further
}

TEST(ThinLines, FarLinesWithTheTurfsChromaKeepTheirPoints) {
  // A JPEG (quality 70, chroma at half resolution) of pale turf, the colour of
  // torso21_kid_800x600's: the far lines, 1-3 px wide, take the turf's chroma, so their peaks
  // are brighter turf rather than white; the light they add over the turf beside them is white.
  testing::SyntheticStyle style;
  style.noise_sigma = 2.0;
  style.turf = cv::Vec3b(78, 148, 126);
  const testing::TestView& view =
      testing::testView("nao-top", "spl", Pose2(-2.0, -1.0, 0.5), style);
  std::vector<uchar> jpeg;
  cv::imencode(".jpg", view.image, jpeg, {cv::IMWRITE_JPEG_QUALITY, 70});
  const cv::Mat image = cv::imdecode(jpeg, cv::IMREAD_COLOR);
  const testing::VisionRun peak_only = runWithBlendWidth(view, image, 0.0),
                           added = runWithBlendWidth(view, image, 4.0);
  // Measured: 37 points beyond 3 m with the peak's colour alone, 57 with the added light; every
  // point within 5 cm of a line either way.
  EXPECT_LE(peak_only.far, 45u);
  EXPECT_GE(added.far, 52u);
  EXPECT_GE(added.score.precision, 0.98);
  EXPECT_LE(added.score.median_error_m, 0.01);
}

}  // namespace
}  // namespace houghloc
