// The ball test of the spot scan (vision/ball_spots.h) on drawn images: a ball's chords are
// found to lie on it, a line, a line crossing and a white disc without patches are not.
#include "vision/ball_spots.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "vision/field_color.h"

namespace houghloc {
namespace {

constexpr int kRadius = 24;  // px, the ball's radius in the drawn images
const cv::Point kCentre(160, 120);
const cv::Scalar kWhite(235, 235, 235);

cv::Mat noisyTurf() {
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(40, 140, 50));
  cv::Mat noise(image.size(), CV_8UC3);
  cv::theRNG().state = 7;
  cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(4));
  cv::Mat noisy;
  cv::add(image, noise, noisy);  // saturating; the mean stays near the turf colour
  return noisy;
}

/// A ball: white disc, black patches in the middle and at four places around it, which leave
/// white chords between them and the rim (a real ball's look that lines' tests accept).
void drawBall(cv::Mat* image, cv::Point centre, int radius) {
  cv::circle(*image, centre, radius, kWhite, cv::FILLED, cv::LINE_AA);
  for (const cv::Point& offset :
       {cv::Point(0, 0), cv::Point(-1, -1), cv::Point(1, -1), cv::Point(-1, 1), cv::Point(1, 1)}) {
    cv::circle(*image, centre + offset * (radius * 5 / 10), radius / 4, cv::Scalar(30, 30, 30),
               cv::FILLED, cv::LINE_AA);
  }
}

class BallSpotsTest : public ::testing::Test {
 protected:
  BallSpotsTest()
      : image_(noisyTurf()),
        color_(estimateFieldColor(image_, std::vector<int>(image_.cols, 0))),
        classes_{color_, static_cast<int>(color_.luma_median) + 5,
                 static_cast<float>(0.4 * std::hypot(color_.r - 1.0 / 3.0, color_.g - 1.0 / 3.0))} {
  }

  bool onBallAt(cv::Point pixel, double radius_px, const BallConfig& config = {}) const {
    LineSpot spot;
    spot.pixel = Eigen::Vector2f(static_cast<float>(pixel.x), static_cast<float>(pixel.y));
    return onBall(Bgr8Pixels(image_), spot, radius_px, classes_, config);
  }

  cv::Mat image_;
  FieldColor color_;
  BallClasses classes_;
};

TEST_F(BallSpotsTest, TurfIsEstimated) {
  ASSERT_TRUE(color_.valid);
  const cv::Vec3b turf = image_.at<cv::Vec3b>(10, 10);
  EXPECT_TRUE(ball_detail::isTurf({turf[0], turf[1], turf[2]}, classes_));
  EXPECT_TRUE(ball_detail::isPatch({30, 30, 30}, classes_));
  EXPECT_FALSE(ball_detail::isPatch({235, 235, 235}, classes_));  // white
  EXPECT_FALSE(ball_detail::isPatch({20, 80, 25}, classes_));     // turf in a shadow
}

TEST_F(BallSpotsTest, ChordsBetweenPatchesAndRimLieOnTheBall) {
  drawBall(&image_, kCentre, kRadius);
  // The white chords above, below and beside the middle patch, and one near the rim.
  for (const cv::Point& chord :
       {kCentre + cv::Point(0, -kRadius * 6 / 10), kCentre + cv::Point(0, kRadius * 6 / 10),
        kCentre + cv::Point(kRadius * 6 / 10, 0),
        kCentre + cv::Point(-kRadius * 8 / 10, kRadius / 8)}) {
    EXPECT_TRUE(onBallAt(chord, kRadius)) << chord;
  }
}

TEST_F(BallSpotsTest, TheBallsSizeMustMatchWithinTheConfiguredRatios) {
  drawBall(&image_, kCentre, kRadius);
  const cv::Point chord = kCentre + cv::Point(0, -kRadius * 6 / 10);
  const BallConfig config;
  // Nominal camera poses put the expected size off by up to 2x (docs/vision.md).
  EXPECT_TRUE(onBallAt(chord, kRadius / 2.0, config));
  EXPECT_TRUE(onBallAt(chord, kRadius * 1.8, config));
  // A blob four times the ball's size is something else (a robot's foot, its body).
  EXPECT_FALSE(onBallAt(chord, kRadius / 4.0, config));
  EXPECT_FALSE(onBallAt(chord, kRadius * 2.5, config));
  BallConfig disabled;
  disabled.enabled = false;
  EXPECT_FALSE(onBallAt(chord, kRadius, disabled));
}

TEST_F(BallSpotsTest, AWhiteDiscWithoutPatchesIsNoBall) {
  // A penalty mark of the ball's size, or a round white object: no dark patches.
  cv::circle(image_, kCentre, kRadius, kWhite, cv::FILLED, cv::LINE_AA);
  EXPECT_FALSE(onBallAt(kCentre + cv::Point(0, -kRadius / 2), kRadius));
}

TEST_F(BallSpotsTest, LinesAndCrossingsAreNoBall) {
  const int width = kRadius;  // a line about as wide as the ball's radius (SPL: 5 cm)
  cv::line(image_, {0, kCentre.y}, {image_.cols - 1, kCentre.y}, kWhite, width, cv::LINE_AA);
  EXPECT_FALSE(onBallAt(kCentre + cv::Point(40, 0), kRadius));  // on the line
  cv::line(image_, {kCentre.x, 0}, {kCentre.x, image_.rows - 1}, kWhite, width, cv::LINE_AA);
  EXPECT_FALSE(onBallAt(kCentre, kRadius));  // at the crossing
  // A ball near the lines (its turf ring clear of them) is still a ball.
  drawBall(&image_, kCentre + cv::Point(80, 60), kRadius);
  EXPECT_TRUE(onBallAt(kCentre + cv::Point(80, 60 - kRadius * 6 / 10), kRadius));
}

TEST_F(BallSpotsTest, ABallCutByTheImageBorderIsNotJudged) {
  drawBall(&image_, {10, kCentre.y}, kRadius);
  EXPECT_FALSE(onBallAt(cv::Point(10, kCentre.y - kRadius * 6 / 10), kRadius));
}

/// The walk to the turf read pixel by pixel: the definition runToTurf must answer like.
int runToTurfEveryPixel(const Bgr8Pixels& pixels, int u, int v, int du, int dv, int limit,
                        const BallClasses& classes) {
  int turf = 0;
  for (int k = 1; k <= limit + ball_detail::kTurfRun - 1; ++k) {
    const int x = u + du * k, y = v + dv * k;
    if (x < 0 || y < 0 || x >= pixels.cols() || y >= pixels.rows()) return -1;
    turf = ball_detail::isTurf(pixels.at(x, y), classes) ? turf + 1 : 0;
    if (turf == ball_detail::kTurfRun) return k - ball_detail::kTurfRun + 1;
  }
  return -1;
}

TEST_F(BallSpotsTest, TheWalkToTheTurfAnswersAsReadingEveryPixel) {
  // Rows of white with turf runs of 1-5 px at random places, some dense, some sparse; walks
  // from every pixel, both ways, with limits short and long and past the image border.
  cv::RNG rng(11);
  for (int v = 0; v < image_.rows; ++v) {
    const double turf_share = 0.05 + 0.5 * v / image_.rows;
    for (int u = 0; u < image_.cols; ++u) {
      if (rng.uniform(0.0, 1.0) < turf_share) {
        u += rng.uniform(0, 5);  // this pixel and the ones skipped keep the turf
      } else {
        image_.at<cv::Vec3b>(v, u) = cv::Vec3b(235, 235, 235);
      }
    }
  }
  const Bgr8Pixels pixels(image_);
  int walks = 0, found = 0;
  for (int v = 0; v < image_.rows; v += 7) {
    for (int u = 0; u < image_.cols; u += 3) {
      for (const int limit : {1, 2, 3, 4, 7, 20, 400}) {
        for (const auto& [du, dv] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const int expected = runToTurfEveryPixel(pixels, u, v, du, dv, limit, classes_);
          ASSERT_EQ(ball_detail::runToTurf(pixels, u, v, du, dv, limit, classes_), expected)
              << "from (" << u << ", " << v << ") along (" << du << ", " << dv << "), limit "
              << limit;
          ++walks;
          found += expected >= 0;
        }
      }
    }
  }
  // Both answers occur often: the comparison covers runs found and walks that end without one.
  EXPECT_GT(found, walks / 5);
  EXPECT_LT(found, walks * 4 / 5);
}

}  // namespace
}  // namespace houghloc
