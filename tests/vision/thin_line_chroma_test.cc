#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "vision/vision_pipeline.h"
#include "vision_test_views.h"

namespace houghloc {
namespace {

struct Found {
  testing::PointScore score;
  size_t far = 0;  ///< points beyond kFarM
};
constexpr double kFarM = 3.0;

Found run(const testing::TestView& view, const cv::Mat& image, double max_blend_width_px) {
  VisionConfig config;
  config.line_width_m = view.field.line_width;
  config.spots.max_blend_width_px = max_blend_width_px;
  VisionPipeline pipeline(view.preset.intrinsics, config);
  const VisionResult result = pipeline.process(image, view.preset.robot_T_camera);
  std::vector<Eigen::Vector2d> points;
  Found found;
  for (const GroundPoint& p : result.ground.points) {
    points.push_back(p.p_robot);
    found.far += p.p_robot.norm() > kFarM ? 1 : 0;
  }
  found.score = testing::scorePoints(view, points);
  return found;
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
  const Found peak_only = run(view, image, 0.0), added = run(view, image, 4.0);
  // Measured: 37 points beyond 3 m with the peak's colour alone, 57 with the added light; every
  // point within 5 cm of a line either way.
  EXPECT_LE(peak_only.far, 45u);
  EXPECT_GE(added.far, 52u);
  EXPECT_GE(added.score.precision, 0.98);
  EXPECT_LE(added.score.median_error_m, 0.01);
}

}  // namespace
}  // namespace houghloc
