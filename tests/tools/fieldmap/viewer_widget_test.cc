// The Qt live viewer on the offscreen platform: messages over memq:// become hypothesis items,
// and a log written from a rendered recording is replayed with the time slider.
#include <gtest/gtest.h>

#include <QApplication>
#include <QSlider>
#include <chrono>
#include <lcm/lcm-cpp.hpp>
#include <memory>

#include "field_models/standard_fields.h"
#include "tools/fieldmap/frame_check/frame_check.h"
#include "tools/fieldmap/viewer/robot_items.h"
#include "tools/fieldmap/viewer/viewer_window.h"
#include "tools/fieldmap/viewer_model/lcm_feed.h"

namespace houghloc::fieldmap {
namespace {

constexpr int kEllipse = static_cast<int>(ViewerItem::kHypothesisEllipse);
constexpr int kPoint = static_cast<int>(ViewerItem::kLinePoint);
constexpr int kTruth = static_cast<int>(ViewerItem::kGroundTruth);

pose_hypothesis_t hypothesis(const Pose2& p, double sigma_m, double weight) {
  pose_hypothesis_t h{};
  h.x = p.x;
  h.y = p.y;
  h.theta = p.theta;
  h.covariance[0] = h.covariance[4] = sigma_m * sigma_m;
  h.covariance[8] = 0.03 * 0.03;
  h.weight = weight;
  return h;
}

pose_hypotheses_t message(std::int64_t utime, const std::vector<Pose2>& poses) {
  pose_hypotheses_t m{};
  m.utime = utime;
  m.status = poses.size() == 1 ? pose_hypotheses_t::TRACKING : pose_hypotheses_t::AMBIGUOUS;
  for (const Pose2& p : poses) m.hypotheses.push_back(hypothesis(p, 0.05, 1.0 / poses.size()));
  m.num_hypotheses = static_cast<int>(poses.size());
  return m;
}

template <typename T>
void writeEvent(lcm::LogFile& log, std::int64_t t_us, const std::string& channel, const T& m) {
  std::vector<std::uint8_t> bytes(m.getEncodedSize());
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  lcm::LogEvent e{};
  e.timestamp = t_us;
  e.channel = channel;
  e.datalen = static_cast<int32_t>(bytes.size());
  e.data = bytes.data();
  ASSERT_EQ(log.writeEvent(&e), 0);
}

/// Writes the channels houghloc-node and houghloc-play would publish for a recorded folder: per
/// frame the check's global localizer poses (HYPOTHESES, 5 cm sigma, equal weights), its line
/// points, a STATUS with the measured time, and the ground truth. Returns the frames.
std::vector<CheckFrame> writeRecordingLog(const std::string& folder, const FieldModel& field,
                                          const std::string& prefix, const std::string& path) {
  FrameSource source(folder);
  lcm::LogFile log(path, "w");
  EXPECT_TRUE(log.good()) << path;
  std::vector<CheckFrame> frames;
  for (int i = 0; i < source.frameCount(); ++i) {
    const auto start = std::chrono::steady_clock::now();
    CheckFrame f = source.frame(i, &field);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (f.ground_truth)
      writeEvent(log, f.t_us, prefix + "GROUND_TRUTH", message(f.t_us, {*f.ground_truth}));
    writeEvent(log, f.t_us, prefix + "HYPOTHESES", message(f.t_us, f.located));
    line_points_t points{};
    points.utime = f.t_us;
    for (const Eigen::Vector2d& p : f.points_robot) {
      points.x.push_back(static_cast<float>(p.x()));
      points.y.push_back(static_cast<float>(p.y()));
    }
    points.num_points = static_cast<int>(points.x.size());
    writeEvent(log, f.t_us, prefix + "LINE_POINTS", points);
    localizer_status_t status{};
    status.utime = f.t_us;
    status.state =
        f.located.size() == 1 ? pose_hypotheses_t::TRACKING : pose_hypotheses_t::AMBIGUOUS;
    status.cycle_time_ms = ms;
    status.points_in = status.points_used = points.num_points;
    status.frames_processed = i + 1;
    writeEvent(log, f.t_us, prefix + "STATUS", status);
    frames.push_back(std::move(f));
  }
  return frames;
}

class ViewerWidget : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "viewer_widget_test";
    static char* argv[] = {name, nullptr};
    app_ = new QApplication(argc, argv);
  }
  static QApplication* app_;
};
QApplication* ViewerWidget::app_ = nullptr;

TEST_F(ViewerWidget, MemqMessagesBecomeHypothesisItems) {
  ViewerWindow window(makeStandardField("spl"), {"NAO3_", "NAO5_"}, "memq://");
  window.show();
  EXPECT_EQ(window.countItems(kEllipse), 0);
  ViewerState state = window.state();
  LcmFeed feed("memq://", &state);
  const pose_hypotheses_t three =
      message(1, {Pose2(1.0, 1.0, 0.0), Pose2(-1.0, -1.0, M_PI), Pose2(3.0, 0.0, 1.0)});
  feed.lcm().publish("NAO3_HYPOTHESES", &three);
  const pose_hypotheses_t one = message(1, {Pose2(-2.0, 2.0, 0.5)});
  feed.lcm().publish("NAO5_HYPOTHESES", &one);
  feed.lcm().publish("NAO5_GROUND_TRUTH", &one);
  ASSERT_EQ(feed.poll(), 3);
  window.showState(state);
  EXPECT_EQ(window.countItems(kEllipse), 4);  // three of NAO3_, one of NAO5_
  EXPECT_EQ(window.countItems(kTruth), 1);
  const pose_hypotheses_t two = message(2, {Pose2(1.0, 1.0, 0.0), Pose2(-1.0, -1.0, M_PI)});
  feed.lcm().publish("NAO3_HYPOTHESES", &two);  // replaces NAO3_'s three
  ASSERT_EQ(feed.poll(), 1);
  window.showState(state);
  EXPECT_EQ(window.countItems(kEllipse), 3);
}

TEST_F(ViewerWidget, TwoSigmaEllipseAxes) {
  double c[9] = {0.04, 0.0, 0, 0.0, 0.01, 0, 0, 0, 0.001};  // sigma x 0.2 m, y 0.1 m
  const Ellipse2 e = twoSigmaEllipse(c);
  EXPECT_NEAR(e.a_m, 0.4, 1e-12);
  EXPECT_NEAR(e.b_m, 0.2, 1e-12);
  EXPECT_NEAR(std::abs(std::sin(e.angle_rad)), 0.0, 1e-12);
}

TEST_F(ViewerWidget, LogSliderReplaysTheRecording) {
  const FieldModel field = makeStandardField("spl");
  const std::string path = ::testing::TempDir() + "/viewer_replay.lcmlog";  // kept for docs
  const std::vector<CheckFrame> frames =
      writeRecordingLog(HOUGHLOC_CHECK_FIXTURE, field, "NAO3_", path);
  ASSERT_EQ(frames.size(), 2u);
  ASSERT_LT(frames[0].t_us, frames[1].t_us);
  ViewerWindow window(field, {"NAO3_"}, QString::fromStdString(path));
  window.setLog(std::make_shared<LogIndex>(path));
  window.show();
  // At the start: frame 0's messages.
  ASSERT_TRUE(window.state().robot("NAO3_").hypotheses.has_value());
  EXPECT_EQ(window.state().robot("NAO3_").hypotheses->utime, frames[0].t_us);
  EXPECT_EQ(window.countItems(kEllipse), static_cast<int>(frames[0].located.size()));
  EXPECT_EQ(window.countItems(kPoint), static_cast<int>(frames[0].points_robot.size()));
  // The slider to the end: frame 1's state.
  QSlider* slider = window.slider();
  ASSERT_TRUE(slider->isVisibleTo(&window));
  EXPECT_EQ(slider->maximum(), static_cast<int>((frames[1].t_us - frames[0].t_us + 999) / 1000));
  slider->setValue(slider->maximum());
  EXPECT_EQ(window.state().robot("NAO3_").hypotheses->utime, frames[1].t_us);
  EXPECT_EQ(window.countItems(kEllipse), static_cast<int>(frames[1].located.size()));
  EXPECT_EQ(window.countItems(kPoint), static_cast<int>(frames[1].points_robot.size()));
  EXPECT_EQ(window.countItems(kTruth), 1);
  EXPECT_EQ(window.state().robot("NAO3_").status->frames_processed, 2);
  slider->setValue(slider->maximum() - 1);  // just before frame 1: frame 0 again
  EXPECT_EQ(window.state().robot("NAO3_").hypotheses->utime, frames[0].t_us);
}

}  // namespace
}  // namespace houghloc::fieldmap
