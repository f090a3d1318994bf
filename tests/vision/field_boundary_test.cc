#include "vision/field_boundary.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <vector>

namespace houghloc {
namespace {

/// Turf below a tilted edge (row 100 at the left, 80 at the right), a white wall with white
/// "lines" above it, a grey robot standing on the field, and a green poster high up.
cv::Mat boundaryImage() {
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(200, 200, 200));
  std::vector<cv::Point> turf = {{0, 100}, {319, 80}, {319, 239}, {0, 239}};
  cv::fillConvexPoly(image, turf, cv::Scalar(50, 150, 60));
  cv::rectangle(image, {140, 60}, {180, 160}, cv::Scalar(90, 90, 90), cv::FILLED);  // robot
  cv::rectangle(image, {250, 10}, {262, 30}, cv::Scalar(50, 150, 60), cv::FILLED);  // poster
  cv::line(image, {0, 40}, {319, 40}, cv::Scalar(255, 255, 255), 3);                // wall line
  return image;
}

TEST(FieldBoundary, FollowsTheTurfEdgeIgnoringOccludersAndClutter) {
  const cv::Mat image = boundaryImage();
  FieldColorConfig color_config;
  const FieldColor color = estimateFieldColor(image, std::vector<int>(image.cols, 0), color_config);
  ASSERT_TRUE(color.valid);
  const FieldBoundary boundary = detectFieldBoundary(image, color, std::vector<int>(image.cols, 0));
  ASSERT_TRUE(boundary.found);
  ASSERT_EQ(boundary.rows.size(), 320u);
  for (int u = 0; u < 320; u += 8) {
    const double expected = 100.0 - 20.0 * u / 319.0;
    EXPECT_NEAR(boundary.rowAt(u), expected, 3.0) << "column " << u;
  }
}

TEST(FieldBoundary, NoTurfNoBoundary) {
  const cv::Mat grey(120, 160, CV_8UC3, cv::Scalar(128, 128, 128));
  const FieldBoundary boundary = detectFieldBoundary(grey, FieldColor{}, std::vector<int>(160, 0));
  EXPECT_FALSE(boundary.found);
  for (float row : boundary.rows) EXPECT_EQ(row, 120.f);
}

TEST(FieldBoundary, StartsNoHigherThanTheHorizon) {
  const cv::Mat image = boundaryImage();
  const FieldColor color = estimateFieldColor(image, std::vector<int>(image.cols, 0));
  const FieldBoundary boundary =
      detectFieldBoundary(image, color, std::vector<int>(image.cols, 150));
  ASSERT_TRUE(boundary.found);
  for (float row : boundary.rows) EXPECT_GE(row, 150.f);
}

}  // namespace
}  // namespace houghloc
