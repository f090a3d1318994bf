#include "tools/offline/trajectory_plot.h"

#include <gtest/gtest.h>

#include <cmath>

#include "field_models/standard_fields.h"

namespace houghloc {
namespace {

/// Pixel of the plot at a field point.
cv::Vec3b at(const cv::Mat& plot, const FieldTopView& view, const Eigen::Vector2d& p) {
  const cv::Point2d px = view.toPixel(p);
  return plot.at<cv::Vec3b>(static_cast<int>(px.y), static_cast<int>(px.x));
}

bool near(const cv::Vec3b& pixel, const cv::Scalar& colour, int tolerance = 10) {
  for (int c = 0; c < 3; ++c) {
    if (std::abs(pixel[c] - static_cast<int>(colour[c])) > tolerance) return false;
  }
  return true;
}

int countColour(const cv::Mat& image, const cv::Scalar& colour) {
  int n = 0;
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) n += near(image.at<cv::Vec3b>(v, u), colour, 0);
  }
  return n;
}

// 60 frames at 10 fps along y = -1 from x = -3 to x = 2.9; the estimate runs 0.4 m to the left
// of the truth, TRACKING for frames 0-19, AMBIGUOUS 20-39, LOST 40-59; a kidnap at frame 30.
TEST(TrajectoryPlot, TruthAndStatusColoursWhereExpected) {
  OfflineContext c;
  c.field = makeStandardField("spl");
  c.recording.folder = "/data/recordings/walk_01/";
  auto truth = [](int i) { return Pose2(-3.0 + 0.1 * i, -1.0, 0.0); };
  std::vector<FrameEstimate> estimates;
  for (int i = 0; i < 60; ++i) {
    FrameRecord f;
    f.t_us = 100000LL * i;
    c.recording.frames.push_back(f);
    c.recording.ground_truth.push_back({f.t_us, truth(i)});
    GaussianPose g;
    g.mean = Pose2(truth(i).x, truth(i).y + 0.4, 0.0);
    g.covariance = Eigen::Vector3d(0.01, 0.0025, 0.01).asDiagonal();
    estimates.push_back({f.t_us, i < 20 ? "TRACKING" : i < 40 ? "AMBIGUOUS" : "LOST", {g}});
  }
  c.recording.events.push_back({c.recording.frames[30].t_us, "KIDNAP"});
  c.end_frame = 60;

  const cv::Mat plot = drawTrajectoryPlot(c, estimates);
  const FieldTopView view(*c.field, trajectoryPlotViewConfig(*c.field));
  ASSERT_EQ(plot.rows, view.image().rows);
  ASSERT_GT(plot.cols, view.image().cols + 100);  // the legend panel on the right

  // The truth line is black where the robot was, and nowhere near it is the carpet black.
  for (int i : {3, 15, 27, 44, 56}) {
    const cv::Vec3b pixel = at(plot, view, truth(i).translation());
    EXPECT_LT(pixel[0] + pixel[1] + pixel[2], 3 * 90) << "frame " << i;
  }
  const cv::Vec3b carpet = at(plot, view, {0.5, -2.0});
  EXPECT_TRUE(near(carpet, trajectoryPlotViewConfig(*c.field).carpet, 3));

  // Best poses in their status colour, 0.4 m left of the truth.
  for (int i : {5, 13}) {
    EXPECT_TRUE(near(at(plot, view, estimates[i].hypotheses[0].mean.translation()),
                     statusColour("TRACKING"), 40))
        << i;
  }
  EXPECT_TRUE(near(at(plot, view, estimates[33].hypotheses[0].mean.translation()),
                   statusColour("AMBIGUOUS"), 40));
  EXPECT_TRUE(near(at(plot, view, estimates[52].hypotheses[0].mean.translation()),
                   statusColour("LOST"), 40));
  // The status colours come from the estimate: hundreds of pixels more than in a plot without
  // estimates (where anti-aliasing may produce a few by chance); no INITIALIZING frame, no grey.
  const cv::Mat empty = drawTrajectoryPlot(c, {});
  const cv::Rect field_area(0, 0, view.image().cols, plot.rows);
  for (const char* status : {"TRACKING", "AMBIGUOUS", "LOST"}) {
    EXPECT_GT(countColour(plot(field_area), statusColour(status)),
              countColour(empty(field_area), statusColour(status)) + 100)
        << status;
  }
  EXPECT_EQ(countColour(plot(field_area), statusColour("INITIALIZING")),
            countColour(empty(field_area), statusColour("INITIALIZING")));
}

TEST(TrajectoryPlot, ScaleKeepsLargeFieldsReadable) {
  for (const std::string& name : standardFieldNames()) {
    const FieldModel field = makeStandardField(name);
    const FieldTopView view(field, trajectoryPlotViewConfig(field));
    EXPECT_GE(view.image().cols, 1300) << name;
    EXPECT_LE(view.image().cols, 1600) << name;
  }
}

}  // namespace
}  // namespace houghloc
