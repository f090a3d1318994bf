#include "tools/drawing/field_top_view.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "field_models/standard_fields.h"

namespace houghloc {
namespace {

const cv::Scalar kRed(0, 0, 255);

bool isRed(const FieldTopView& view, const Eigen::Vector2d& p_field) {
  const cv::Point2d px = view.toPixel(p_field);
  const cv::Vec3b c = view.image().at<cv::Vec3b>(static_cast<int>(std::floor(px.y)),
                                                 static_cast<int>(std::floor(px.x)));
  return c[2] > 150 && c[1] < 120 && c[0] < 120;
}

TEST(FieldTopViewTest, PixelMappingAndSize) {
  const FieldModel spl = makeStandardField("spl");
  FieldTopViewConfig config;
  config.pixels_per_metre = 50.0;
  config.margin_px = 10;
  const FieldTopView view(spl, config);
  EXPECT_EQ(view.image().cols, 520 + 20);
  EXPECT_EQ(view.image().rows, 370 + 20);
  const cv::Point2d corner = view.toPixel({-5.2, 3.7});  // top left of the carpet
  EXPECT_DOUBLE_EQ(corner.x, 10.0);
  EXPECT_DOUBLE_EQ(corner.y, 10.0);
  const cv::Point2d centre = view.toPixel({0.0, 0.0});
  EXPECT_DOUBLE_EQ(centre.x, 10.0 + 260.0);
  EXPECT_DOUBLE_EQ(centre.y, 10.0 + 185.0);
  const Eigen::Vector2d back = view.toField(view.toPixel({1.23, -2.5}));
  EXPECT_NEAR(back.x(), 1.23, 1e-12);
  EXPECT_NEAR(back.y(), -2.5, 1e-12);

  config.pixels_per_metre = 5000.0;  // 52000 px wide
  EXPECT_THROW((FieldTopView{spl, config}), std::invalid_argument);
  FieldModel broken = spl;
  broken.field_length = std::nan("");
  EXPECT_THROW(FieldTopView{broken}, std::invalid_argument);
}

TEST(FieldTopViewTest, PoseAndCovarianceEllipse) {
  FieldTopView view(makeStandardField("spl"));  // 100 px/m, background only: nothing red
  // Ellipse with sigmas 0.4 m along the 45 degree diagonal and 0.1 m across, drawn at 1 sigma.
  const double c = std::cos(M_PI / 4), s = std::sin(M_PI / 4);
  Eigen::Matrix2d rotation;
  rotation << c, -s, s, c;
  const Eigen::Matrix2d cov =
      rotation * Eigen::Vector2d(0.16, 0.01).asDiagonal() * rotation.transpose();
  const Eigen::Vector2d mean(-2.0, 1.0);
  view.drawCovarianceEllipse(mean, cov, kRed, 1.0);
  EXPECT_TRUE(isRed(view, mean + 0.4 * Eigen::Vector2d(c, s)));
  EXPECT_TRUE(isRed(view, mean - 0.4 * Eigen::Vector2d(c, s)));
  EXPECT_TRUE(isRed(view, mean + 0.1 * Eigen::Vector2d(-s, c)));
  EXPECT_FALSE(isRed(view, mean));
  EXPECT_FALSE(isRed(view, mean + 0.4 * Eigen::Vector2d(-s, c)));  // not along the minor axis

  // A robot at (2, -1) facing +y: circle of 0.15 m and a heading line toward +y.
  view.drawPose(Pose2(2.0, -1.0, M_PI / 2), kRed);
  EXPECT_TRUE(isRed(view, {2.0, -1.0 + 0.2}));         // heading line beyond the circle
  EXPECT_FALSE(isRed(view, {2.0, -1.0 - 0.2}));        // nothing behind
  EXPECT_TRUE(isRed(view, {2.0 + 0.15, -1.0}));        // circle
  view.drawPose(Pose2(std::nan(""), 0.0, 0.0), kRed);  // ignored, no crash
}

}  // namespace
}  // namespace houghloc
