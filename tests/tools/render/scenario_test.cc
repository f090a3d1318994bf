#include "tools/render/scenario.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace houghloc {
namespace {

std::string writeTemp(const std::string& name, const std::string& text) {
  // ctest runs every test in a process of its own, two at a time: one file per test (a shared
  // bad.yaml let one test read another's text).
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const auto path =
      std::filesystem::temp_directory_path() / ("houghloc_scenario_" + test + "_" + name);
  std::ofstream(path) << "%YAML:1.0\n---\n" << text;
  return path.string();
}

std::string loadError(const std::string& text) {
  try {
    loadScenario(writeTemp("bad.yaml", text));
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioTest, AllOptionsExampleLoads) {
  const Scenario s = loadScenario(HOUGHLOC_SOURCE_DIR "/tools/render/scenarios/all_options.yaml");
  EXPECT_EQ(s.trajectory.name, "waypoints");
  EXPECT_EQ(s.trajectory.waypoints.size(), 3u);
  EXPECT_EQ(s.head.schedule.size(), 3u);
  ASSERT_EQ(s.kidnaps.size(), 2u);
  ASSERT_TRUE(s.kidnaps[0].to.has_value());
  EXPECT_NEAR(s.kidnaps[0].to->theta, M_PI, 1e-9);
  EXPECT_EQ(s.falls.size(), 1u);
  EXPECT_EQ(s.robots.size(), 2u);
  EXPECT_EQ(s.scene.people, 12);
  EXPECT_EQ(s.sensor.supersampling, 2);
  EXPECT_EQ(s.sensor.light_changes.size(), 1u);
  EXPECT_NEAR(s.camera_pose_error.bias.pitch, -M_PI / 180.0, 1e-12);
  EXPECT_EQ(s.hints.size(), 3u);
  ASSERT_TRUE(s.camera_mount.has_value());
  EXPECT_NEAR(s.camera_mount->z, 0.51, 1e-12);
  EXPECT_EQ(s.scene.turf_bgr[2], 78.0);
  EXPECT_EQ(s.scene.paint_bgr[0], 210.0);
  EXPECT_EQ(s.scene.hall_brightness, 0.9);
  EXPECT_EQ(s.sensor.tint, 0.1);
}

TEST(ScenarioTest, BuiltInNameAsString) {
  const Scenario s = loadScenario(writeTemp("spin.yaml", "trajectory: spin\nframes: 5\n"));
  EXPECT_EQ(s.trajectory.name, "spin");
  EXPECT_EQ(s.frames, 5);
}

TEST(ScenarioTest, UnknownKeysAreNamed) {
  EXPECT_NE(loadError("scene:\n  turf_txture: true\n").find("scene.turf_txture: unknown key"),
            std::string::npos);
  EXPECT_NE(loadError("fpss: 30\n").find("fpss: unknown key"), std::string::npos);
  EXPECT_NE(loadError("robots:\n  - { x_m: 1, colour: red }\n").find("robots[0].colour"),
            std::string::npos);
}

TEST(ScenarioTest, WrongTypesAndRangesAreNamed) {
  EXPECT_NE(loadError("fps: fast\n").find("fps: expected a number"), std::string::npos);
  EXPECT_NE(loadError("scene:\n  goals: maybe\n").find("scene.goals: expected true or false"),
            std::string::npos);
  EXPECT_NE(loadError("trajectory: jog\n").find("trajectory.name: unknown trajectory 'jog'"),
            std::string::npos);
  EXPECT_NE(loadError("sensor:\n  jpeg_quality: 101\n").find("sensor.jpeg_quality"),
            std::string::npos);
  EXPECT_NE(loadError("trajectory:\n  waypoints:\n    - [1, 2]\n").find("waypoints[0]"),
            std::string::npos);
}

TEST(ScenarioTest, CarpetPaintHallAndTintAreChecked) {
  EXPECT_NE(
      loadError("scene:\n  turf_bgr: [90, 95]\n").find("scene.turf_bgr: expected a list of 3"),
      std::string::npos);
  EXPECT_NE(loadError("scene:\n  turf_bgr: [90, 95, 300]\n").find("scene.turf_bgr: components"),
            std::string::npos);
  EXPECT_NE(loadError("scene:\n  paint_bgr: [-1, 200, 200]\n").find("scene.paint_bgr"),
            std::string::npos);
  EXPECT_NE(loadError("scene:\n  hall_brightness: 5\n").find("scene.hall_brightness"),
            std::string::npos);
  EXPECT_NE(loadError("sensor:\n  tint: -1.5\n").find("sensor.tint: must be in [-1, 1]"),
            std::string::npos);
  EXPECT_NE(loadError("scene:\n  turf_colour: [1, 2, 3]\n").find("scene.turf_colour: unknown key"),
            std::string::npos);
  const Scenario s = loadScenario(writeTemp("grey.yaml", "scene:\n  turf_bgr: [96, 100, 100]\n"));
  EXPECT_EQ(s.scene.turf_bgr[0], 96.0);
  EXPECT_EQ(s.scene.paint_bgr[0], 222.0);  // untouched defaults
  EXPECT_EQ(s.sensor.tint, 0.0);
}

}  // namespace
}  // namespace houghloc
