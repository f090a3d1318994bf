// houghloc-render's fault options (docs/render.md "Faults"): the YAML schema, and a small
// render with each fault in its own window against the same render without faults. Outside
// the windows the folders must be byte-identical; inside, each fault shows as specified.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "field_models/standard_fields.h"
#include "tools/recording/recording.h"
#include "tools/render/faults.h"
#include "tools/render/recording_renderer.h"
#include "vision/camera_presets.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

std::string loadError(const std::string& text) {
  const fs::path path = fs::temp_directory_path() / "houghloc_fault_options_bad.yaml";
  std::ofstream(path) << "%YAML:1.0\n---\n" << text;
  try {
    loadScenario(path.string());
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(FaultOptions, YamlNamesTheKeyAtFault) {
  EXPECT_TRUE(contains(loadError("faults:\n  - { kind: motion_blur, start_s: 1, end_s: 2, "
                                 "delay_ms: 100 }\n"),
                       "faults[0].delay_ms: unknown key"));
  EXPECT_TRUE(contains(loadError("faults:\n  - { kind: earthquake, start_s: 1, end_s: 2 }\n"),
                       "faults[0].kind: unknown fault 'earthquake'"));
  EXPECT_TRUE(contains(loadError("faults:\n  - { kind: odometry_dropout, start_s: 2, end_s: 1 }\n"),
                       "faults[0].end_s: must be after start_s"));
  EXPECT_TRUE(contains(loadError("faults:\n  - { kind: light_change, start_s: 1, end_s: 1.2, "
                                 "ramp_s: 0.2 }\n"),
                       "faults[0].ramp_s"));
  EXPECT_TRUE(contains(loadError("faults:\n  - { kind: robots_in_view, start_s: 1, end_s: 2, "
                                 "team: purple }\n"),
                       "faults[0].team: unknown colour 'purple'"));
  EXPECT_EQ(loadError("faults:\n  - { kind: camera_pose_delay, start_s: 1, end_s: 2, "
                      "delay_ms: 50 }\n  - { kind: odometry_dropout, start_s: 1, end_s: 1.1 }\n"),
            "");
}

TEST(FaultOptions, LightRampsInAndOutWithinTheWindow) {
  FaultConfig light;
  light.kind = "light_change";
  light.start_s = 1.0;
  light.end_s = 3.0;
  light.exposure = 0.4;
  light.ramp_s = 0.5;
  const std::vector<FaultConfig> faults = {light};
  const ExposureState base{1.0, 5500.0};
  EXPECT_DOUBLE_EQ(applyLightFaults(base, faults, 0.99).gain, 1.0);
  EXPECT_NEAR(applyLightFaults(base, faults, 1.25).gain, 0.7, 1e-12);  // half way in
  EXPECT_NEAR(applyLightFaults(base, faults, 2.0).gain, 0.4, 1e-12);
  EXPECT_NEAR(applyLightFaults(base, faults, 2.0).color_temperature_k, 3000.0, 1e-9);
  EXPECT_NEAR(applyLightFaults(base, faults, 2.75).gain, 0.7, 1e-12);  // half way out
  EXPECT_DOUBLE_EQ(applyLightFaults(base, faults, 3.0).gain, 1.0);
}

TEST(FaultOptions, RobotsStandInFrontOfTheCamera) {
  FaultConfig robots;
  robots.kind = "robots_in_view";
  robots.start_s = 0.0;
  robots.end_s = 1.0;
  const Pose2 self(1.0, 2.0, 0.5);
  const double pan = 0.3;
  EXPECT_TRUE(faultRobots({robots}, 1.0, self, pan, 0.58).shadows.empty());
  const SceneObjects objects = faultRobots({robots}, 0.5, self, pan, 0.58);
  ASSERT_EQ(objects.shadows.size(), 3u);  // one contact shadow per robot
  for (size_t i = 0; i < 3; ++i) {
    const Eigen::Vector2d offset = objects.shadows[i].center.cast<double>() - self.translation();
    EXPECT_NEAR(offset.norm(), 1.0, 1e-5);
    const double bearing = std::atan2(offset.y(), offset.x()) - self.theta;
    EXPECT_NEAR(bearing, pan + (i - 1.0) * 20.0 * M_PI / 180.0, 1e-5);
  }
}

/// A 160x120 nao-top render of 20 frames (0.63 s of walking), with or without faults.
Recording render(const std::string& name, const std::vector<FaultConfig>& faults,
                 const OdometryConfig& odometry = {}) {
  RenderJob job;
  job.field = makeStandardField("spl");
  const CameraPreset preset = cameraPreset("nao-top");
  job.intrinsics = preset.intrinsics;
  job.intrinsics.image_width /= 4;
  job.intrinsics.image_height /= 4;
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 3; ++c) job.intrinsics.camera_matrix(r, c) /= 4.0;
  }
  job.mount = preset.robot_T_camera;
  job.scenario.frames = 20;
  job.scenario.seed = 5;
  job.scenario.sensor.image_format = "png";
  job.scenario.faults = faults;
  job.scenario.odometry = odometry;
  job.out_dir = (fs::path(::testing::TempDir()) / ("houghloc_fault_options_" + name)).string();
  fs::remove_all(job.out_dir);
  renderRecording(job);
  return readRecording(job.out_dir);
}

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

FaultConfig fault(const std::string& kind, int first_frame, int end_frame) {
  FaultConfig f;
  f.kind = kind;
  f.start_s = first_frame / 30.0;
  f.end_s = end_frame / 30.0;
  f.ramp_s = 0.0;
  return f;
}

TEST(FaultOptions, EachFaultChangesOnlyItsWindow) {
  // Frames [3, 6) odometry dropout, [6, 9) pose delay, [9, 12) light, [12, 15) robots,
  // [15, 18) blur; 18 and 19 clean again.
  const std::vector<FaultConfig> faults = {
      fault("odometry_dropout", 3, 6), fault("camera_pose_delay", 6, 9),
      fault("light_change", 9, 12), fault("robots_in_view", 12, 15), fault("motion_blur", 15, 18)};
  const Recording clean = render("clean", {});
  const Recording faulty = render("faulty", faults);
  ASSERT_EQ(faulty.frames.size(), 20u);
  auto image = [](const Recording& rec, int i) {
    return fileBytes(fs::path(rec.folder) / rec.frames[i].image);
  };
  for (int i = 0; i < 20; ++i) {
    const FrameRecord& f = faulty.frames[i];
    const FrameRecord& c = clean.frames[i];
    SCOPED_TRACE("frame " + std::to_string(i));
    // Odometry: none during the dropout (empty fields), then the true cumulative pose again.
    ASSERT_TRUE(c.odometry);
    if (i >= 3 && i < 6) {
      EXPECT_FALSE(f.odometry);
    } else {
      ASSERT_TRUE(f.odometry);
      EXPECT_EQ(f.odometry->x, c.odometry->x);
      EXPECT_EQ(f.odometry->theta, c.odometry->theta);
    }
    // Camera pose: 100 ms (3 frames) late during the delay.
    const Pose3& pose = i >= 6 && i < 9 ? clean.frames[i - 3].robot_T_camera : c.robot_T_camera;
    EXPECT_NEAR(f.robot_T_camera.yaw, pose.yaw, 1e-9);
    EXPECT_NEAR(f.robot_T_camera.pitch, pose.pitch, 1e-9);
    EXPECT_NEAR(f.robot_T_camera.z, pose.z, 1e-9);
    const bool image_fault = i >= 9 && i < 18;
    EXPECT_EQ(image(faulty, i) == image(clean, i), !image_fault);
    if (i >= 9 && i < 12) {
      const cv::Scalar dark = cv::mean(cv::imread(fs::path(faulty.folder) / f.image));
      const cv::Scalar bright = cv::mean(cv::imread(fs::path(clean.folder) / c.image));
      const double ratio = (dark[0] + dark[1] + dark[2]) / (bright[0] + bright[1] + bright[2]);
      EXPECT_NEAR(ratio, 0.35, 0.07);  // the gain, blurred by noise floor and the colour shift
    }
  }
  // The robots hide lines: truth/visible.csv shows less of the map in their frames.
  auto visible = [](const Recording& rec, int from, int to) {
    double sum = 0.0;
    for (const VisibleRecord& v : rec.visible) {
      if (v.t_us >= rec.frames[from].t_us && v.t_us < rec.frames[to].t_us) {
        sum += v.visible_length_m;
      }
    }
    return sum;
  };
  EXPECT_LT(visible(faulty, 12, 15), 0.8 * visible(clean, 12, 15));
  EXPECT_NEAR(visible(faulty, 0, 12), visible(clean, 0, 12), 1e-12);
  // truth/faults.csv: one row per window.
  const std::string rows = fileBytes(fs::path(faulty.folder) / "truth" / "faults.csv");
  EXPECT_EQ(rows.substr(0, rows.find('\n')), "t_start_us,t_end_us,fault");
  EXPECT_TRUE(contains(rows, "\n100000,200000,odometry_dropout\n")) << rows;
  EXPECT_TRUE(contains(rows, ",600000,motion_blur\n")) << rows;
  EXPECT_FALSE(fs::exists(fs::path(clean.folder) / "truth" / "faults.csv"));
}

TEST(FaultOptions, OdometryScalePitchErrorAndDroppedFramesChangeOnlyTheirWindow) {
  // Frames [3, 6) odometry x1.3, [6, 9) camera pitch +2 deg, [12, 18) half the frames dropped.
  FaultConfig scale = fault("odometry_scale", 3, 6), pitch = fault("camera_pitch_error", 6, 9);
  FaultConfig drop = fault("frame_drop", 12, 18);
  // Odometry without noise, bias or slips, so that a step's scale shows exactly.
  const OdometryConfig exact{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.6, 0.4};
  const Recording clean = render("clean_exact_odometry", {}, exact);
  const Recording faulty = render("scaled_pitched_dropped", {scale, pitch, drop}, exact);
  std::map<std::int64_t, const FrameRecord*> recorded;
  for (const FrameRecord& f : faulty.frames) recorded[f.t_us] = &f;
  EXPECT_EQ(faulty.ground_truth.size(), 20u) << "truth goes on through dropped frames";
  int dropped = 0;
  double scaled_walk = 0.0, clean_walk = 0.0;
  for (int i = 0; i < 20; ++i) {
    SCOPED_TRACE("frame " + std::to_string(i));
    const FrameRecord& c = clean.frames[i];
    const auto it = recorded.find(c.t_us);
    if (it == recorded.end()) {
      EXPECT_TRUE(i >= 12 && i < 18) << "dropped outside the frame_drop window";
      ++dropped;
      continue;
    }
    const FrameRecord& f = *it->second;
    EXPECT_EQ(fileBytes(fs::path(faulty.folder) / f.image),
              fileBytes(fs::path(clean.folder) / c.image));
    ASSERT_TRUE(f.odometry && c.odometry);
    if (i >= 3 && i < 6) {
      const FrameRecord& fp = faulty.frames[i - 1];
      const FrameRecord& cp = clean.frames[i - 1];
      const Pose2 f_step = fp.odometry->inverse() * *f.odometry;
      const Pose2 c_step = cp.odometry->inverse() * *c.odometry;
      scaled_walk += std::hypot(f_step.x, f_step.y);
      clean_walk += std::hypot(c_step.x, c_step.y);
    }
    if (i < 3) {
      EXPECT_EQ(f.odometry->x, c.odometry->x);
    }
    const double pitch_error = i >= 6 && i < 9 ? 2.0 * M_PI / 180.0 : 0.0;
    EXPECT_NEAR(f.robot_T_camera.pitch, c.robot_T_camera.pitch + pitch_error, 1e-9);
    EXPECT_NEAR(f.robot_T_camera.yaw, c.robot_T_camera.yaw, 1e-9);
  }
  ASSERT_GT(clean_walk, 0.0);
  EXPECT_NEAR(scaled_walk / clean_walk, 1.3, 1e-9);
  EXPECT_GT(dropped, 0);
  EXPECT_LT(dropped, 6);
}

}  // namespace
}  // namespace houghloc
