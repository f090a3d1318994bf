// Rendered folders against the map projected at the ground-truth pose (issue 4): lines land on
// white pixels, turf away from lines is green, truth/visible.csv matches the projection.
#include <gtest/gtest.h>

#include <cstdlib>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "field_models/field_distance.h"
#include "tests/tools/render/render_test_util.h"
#include "tools/recording/recording.h"

namespace houghloc {
namespace {

struct Case {
  std::string field, camera;
  bool along_line = false;  ///< walk along the halfway line (for the steep nao-bottom view)
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.field << " / " << c.camera; }

double luma(const cv::Vec3b& p) { return 0.114 * p[0] + 0.587 * p[1] + 0.299 * p[2]; }
bool isGreen(const cv::Vec3b& p) { return p[1] > p[2] + 15 && p[1] > p[0] + 15; }
/// White paint: bright and nearly grey. Judged by chroma rather than a fixed brightness, since
/// vignetting and the hall lighting darken the corners (turf has G - min(B, R) ~ 0.6 G).
bool isWhite(const cv::Vec3b& p) {
  return luma(p) > 90.0 && p[1] - std::min(p[0], p[2]) < 0.3 * p[1];
}

/// Samples along every line feature (field frame) with the local line direction.
struct LineSample {
  Eigen::Vector2d p, dir;
  std::string feature;
};
std::vector<LineSample> lineSamples(const FieldModel& field, double step) {
  std::vector<LineSample> out;
  for (size_t i = 0; i < field.segments.size(); ++i) {
    const Segment2& s = field.segments[i];
    const int n = static_cast<int>(s.length() / step);
    for (int k = 0; k <= n; ++k) {
      out.push_back({s.a + (s.b - s.a) * (double(k) / std::max(1, n)), s.direction(),
                     describeFeature({FeatureKind::kSegment, int(i)})});
    }
  }
  for (size_t i = 0; i < field.arcs.size(); ++i) {
    const Arc2& a = field.arcs[i];
    const int n = static_cast<int>(a.length() / step);
    for (int k = 0; k <= n; ++k) {
      const double angle = a.start_rad + a.sweep_rad * k / std::max(1, n);
      out.push_back({a.pointAt(angle), Eigen::Vector2d(-std::sin(angle), std::cos(angle)),
                     describeFeature({FeatureKind::kArc, int(i)})});
    }
  }
  return out;
}

class RenderOutputTest : public ::testing::TestWithParam<Case> {
 protected:
  static constexpr int kFrames = 8;
  void SetUp() override {
    job_ = testJob(GetParam().field, GetParam().camera,
                   "output_" + GetParam().field + "_" + GetParam().camera);
    Scenario& s = job_.scenario;
    s.frames = kFrames;
    s.fps = 3.0;  // far apart frames: more different views
    s.seed = 11;
    // Occluders off; everything else (texture, wear, noise, blur, JPEG) as by default.
    s.scene.goals = false;
    s.scene.people = 0;
    s.scene.own_feet = false;
    s.ball.enabled = false;
    if (GetParam().along_line) {
      s.trajectory.name = "waypoints";
      s.trajectory.waypoints = {{-0.45, -2.0, 0.0, 0.25}, {-0.45, 2.0, 0.0, 0.25}};
    }
    renderRecording(job_);
    rec_ = readRecording(job_.out_dir);
  }
  // The checks of one rendered folder (a render takes seconds, tens under the sanitizers, so
  // each case renders once and runs every check on it).
  void mapLinesLandOnWhiteAndTurfIsGreen();
  void rigCamerasTakeTurnsAndEachHasItsFile();
  void visibleCsvMatchesTheProjectedMap();
  RenderJob job_;
  Recording rec_;
};

void RenderOutputTest::mapLinesLandOnWhiteAndTurfIsGreen() {
  const FieldModel& field = job_.field;
  const std::vector<LineSample> samples = lineSamples(field, 0.02);
  int white = 0, lines = 0, green = 0, turf = 0;
  std::string first_failure;
  for (const FrameRecord& frame : rec_.frames) {
    const cv::Mat3b image = cv::imread(job_.out_dir + "/" + frame.image);
    cv::Mat3b debug = image.clone();
    const Pose2 truth = *groundTruthAt(rec_.ground_truth, frame.t_us);
    const CameraModel camera(rec_.intrinsicsFor(frame), frame.robot_T_camera);
    const Pose2 robot_T_field = truth.inverse();
    auto pixelOf = [&](const Eigen::Vector2d& p_field) -> std::optional<Eigen::Vector2d> {
      const Eigen::Vector2d p = robot_T_field.transform(p_field);
      const auto px = camera.project(Eigen::Vector3d(p.x(), p.y(), 0.0));
      if (!px || px->x() < 3 || px->y() < 3 || px->x() > camera.width() - 4 ||
          px->y() > camera.height() - 4) {
        return std::nullopt;
      }
      return px;
    };
    // Line samples whose painted width is at least 2 px across the line in the image.
    const double hw = 0.5 * field.line_width;
    for (const LineSample& s : samples) {
      const Eigen::Vector2d n(-s.dir.y(), s.dir.x());
      const auto c = pixelOf(s.p), a = pixelOf(s.p + hw * n), b = pixelOf(s.p - hw * n);
      const auto f = pixelOf(s.p + 0.02 * s.dir), r = pixelOf(s.p - 0.02 * s.dir);
      if (!c || !a || !b || !f || !r || (*f - *r).norm() < 1e-6) continue;
      // Width across the line's image (the projected ground normal is oblique to it).
      const Eigen::Vector2d along = (*f - *r).normalized(), across = *a - *b;
      if (std::abs(along.x() * across.y() - along.y() * across.x()) < 2.0) continue;
      ++lines;
      const cv::Vec3b px = image(int(std::lround(c->y())), int(std::lround(c->x())));
      if (std::getenv("RENDER_TEST_DEBUG")) {
        cv::circle(debug, cv::Point(int(std::lround(c->x())), int(std::lround(c->y()))), 1,
                   isWhite(px) ? cv::Scalar(255, 0, 0) : cv::Scalar(0, 0, 255), -1);
      }
      if (isWhite(px)) {
        ++white;
      } else if (first_failure.empty()) {
        first_failure = s.feature + " at pixel " + std::to_string(c->x()) + "," +
                        std::to_string(c->y()) + " luma " + std::to_string(luma(px));
      }
    }
    // Turf at least 0.3 m from every line, on a grid over the carpet.
    // (and 0.3 m inside the carpet's edge, where the gym floor begins)
    const double ex = field.outerHalfLength() - 0.3, ey = field.outerHalfWidth() - 0.3;
    const double step = GetParam().along_line ? 0.03 : 0.1;
    for (double x = -ex; x <= ex; x += step) {
      for (double y = -ey; y <= ey; y += step) {
        if (nearestFeature(field, {x, y}).distance_m < 0.3) continue;
        const auto c = pixelOf({x, y});
        if (!c) continue;
        // Only where 0.3 m on the ground spans several pixels (not near the horizon, where a
        // pixel covers metres of turf, lines and the floor beyond).
        const auto g0 = camera.pixelToGround(c->x(), c->y());
        const auto gu = camera.pixelToGround(c->x() + 1.0, c->y());
        const auto gv = camera.pixelToGround(c->x(), c->y() + 1.0);
        const bool resolved =
            g0 && gu && gv && (*gu - *g0).norm() < 0.05 && (*gv - *g0).norm() < 0.05;
        if (!resolved) continue;
        ++turf;
        const cv::Vec3b px = image(int(std::lround(c->y())), int(std::lround(c->x())));
        green += isGreen(px);
        if (!isGreen(px) && std::getenv("RENDER_TEST_DEBUG")) {
          cv::circle(debug, cv::Point(int(std::lround(c->x())), int(std::lround(c->y()))), 2,
                     cv::Scalar(255, 0, 255), -1);
        }
        if (!isGreen(px) && first_failure.empty()) {
          first_failure = "turf at " + std::to_string(x) + "," + std::to_string(y) + " pixel " +
                          std::to_string(c->x()) + "," + std::to_string(c->y());
        }
      }
    }
    if (std::getenv("RENDER_TEST_DEBUG")) {
      cv::imwrite(job_.out_dir + "/debug_" + std::to_string(frame.t_us) + ".png", debug);
    }
  }
  ASSERT_GT(lines, 100);
  ASSERT_GT(turf, 100);
  // Worn patches and sensor noise allow a very few misses.
  EXPECT_GE(white, 0.99 * lines) << white << " of " << lines << ", first miss: " << first_failure;
  EXPECT_GE(green, 0.995 * turf) << green << " of " << turf << ", first miss: " << first_failure;
}

void RenderOutputTest::rigCamerasTakeTurnsAndEachHasItsFile() {
  if (job_.rig.empty()) {
    EXPECT_TRUE(rec_.camera.has_value());
    for (const FrameRecord& frame : rec_.frames) EXPECT_EQ(frame.camera_id, "");
    return;
  }
  ASSERT_EQ(rec_.cameras.size(), job_.rig.size());
  for (size_t i = 0; i < rec_.frames.size(); ++i) {
    const FrameRecord& frame = rec_.frames[i];
    const RigCamera& expected = job_.rig[i % job_.rig.size()];
    EXPECT_EQ(frame.camera_id, expected.id);
    const cv::Mat image = cv::imread(job_.out_dir + "/" + frame.image);
    EXPECT_EQ(image.cols, expected.intrinsics.image_width);
    EXPECT_EQ(image.rows, expected.intrinsics.image_height);
    // The recorded pose is the camera's own mount turned by the head, not the other camera's.
    EXPECT_NEAR(frame.robot_T_camera.pitch, expected.mount.pitch, 0.2) << i;
  }
}

void RenderOutputTest::visibleCsvMatchesTheProjectedMap() {
  const FieldModel& field = job_.field;
  const std::vector<LineSample> samples = lineSamples(field, 0.01);
  for (const FrameRecord& frame : rec_.frames) {
    const Pose2 truth = *groundTruthAt(rec_.ground_truth, frame.t_us);
    const CameraModel camera(rec_.intrinsicsFor(frame), frame.robot_T_camera);
    std::map<std::string, double> expected, written;
    for (const LineSample& s : samples) {
      if ((s.p - truth.translation()).norm() > 4.0) continue;
      const Eigen::Vector2d p = truth.inverse().transform(s.p);
      const auto px = camera.project(Eigen::Vector3d(p.x(), p.y(), 0.0));
      if (px && camera.inImage(*px)) expected[s.feature] += 0.01;
    }
    for (const VisibleRecord& v : rec_.visible) {
      if (v.t_us == frame.t_us && v.feature.rfind("marks", 0) != 0) {
        written[v.feature] = v.visible_length_m;
      }
    }
    for (const auto& [feature, length] : expected) {
      EXPECT_NEAR(written[feature], length, 0.05 + 0.03 * length) << feature << " t=" << frame.t_us;
    }
    for (const auto& [feature, length] : written) {
      EXPECT_TRUE(expected.count(feature) || length < 0.05) << feature;
    }
  }
}

TEST_P(RenderOutputTest, RenderedFolderMatchesTheMap) {
  {
    SCOPED_TRACE("map lines land on white and turf is green");
    mapLinesLandOnWhiteAndTurfIsGreen();
  }
  {
    SCOPED_TRACE("rig cameras take turns and each has its file");
    rigCamerasTakeTurnsAndEachHasItsFile();
  }
  SCOPED_TRACE("truth/visible.csv matches the projected map");
  visibleCsvMatchesTheProjectedMap();
}

INSTANTIATE_TEST_SUITE_P(FieldsAndCameras, RenderOutputTest,
                         ::testing::Values(Case{"spl", "nao-top"}, Case{"spl", "nao-bottom", true},
                                           Case{"kid", "kid-wide"}, Case{"adult", "adult"},
                                           Case{"msl", "nao-top"}, Case{"spl", "nao"}),
                         [](const auto& info) {
                           std::string n = info.param.field + "_" + info.param.camera;
                           for (char& c : n) c = (c == '-') ? '_' : c;
                           return n;
                         });

}  // namespace
}  // namespace houghloc
