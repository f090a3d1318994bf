// houghloc-offline as a user runs it: exit codes and messages for good and bad folders.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>

#include "tools/recording/recording.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

struct RunResult {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr
};

RunResult run(const std::string& args) {
  const std::string command = std::string(HOUGHLOC_OFFLINE_EXE) + " " + args + " 2>&1";
  RunResult result;
  FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe)) result.output += buffer.data();
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A tiny folder: 160x120 pinhole camera 0.5 m high looking 30 deg down, 4 frames of turf with
/// a white line across.
class OfflineCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ("offline_cli_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "images");
    Recording rec;
    CameraIntrinsics camera;
    camera.image_width = 160;
    camera.image_height = 120;
    camera.camera_matrix = cv::Matx33d(150, 0, 79.5, 0, 150, 59.5, 0, 0, 1);
    rec.camera = camera;
    for (int i = 0; i < 4; ++i) {
      FrameRecord frame;
      frame.image = "images/" + std::to_string(i) + ".png";
      frame.t_us = 100000 * i;
      frame.robot_T_camera.z = 0.5;
      frame.robot_T_camera.pitch = 0.5;
      rec.frames.push_back(frame);
      cv::Mat image(120, 160, CV_8UC3, cv::Scalar(50, 140, 60));
      cv::line(image, {0, 80}, {159, 78}, cv::Scalar(235, 235, 235), 3);
      cv::imwrite((dir_ / frame.image).string(), image);
    }
    writeRecording(rec, dir_.string());
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
};

TEST_F(OfflineCli, VisionOnlyWritesPointsWithTheDesignHeader) {
  const RunResult r = run(dir_.string() + " --vision-only --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string points = readFile(dir_ / "houghloc" / "points.csv");
  EXPECT_EQ(points.substr(0, points.find('\n')), "t_us,u,v,x_robot,y_robot");
  EXPECT_GT(std::count(points.begin(), points.end(), '\n'), 4) << points;
  EXPECT_TRUE(fs::exists(dir_ / "houghloc" / "timing.csv"));
  EXPECT_NE(r.output.find("frames processed 4"), std::string::npos) << r.output;
}

TEST_F(OfflineCli, StartEndAndOutAndOverlay) {
  const fs::path out = dir_ / "elsewhere";
  const RunResult r =
      run(dir_.string() + " --vision-only --quiet --overlay --start 1 --end 3 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string points = readFile(out / "points.csv");
  EXPECT_EQ(points.find("\n0,"), std::string::npos);
  EXPECT_EQ(points.find("\n300000,"), std::string::npos);
  EXPECT_NE(points.find("\n100000,"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "overlay" / "1.png"));
  EXPECT_FALSE(fs::exists(out / "overlay" / "0.png"));
}

TEST_F(OfflineCli, MissingImageIsSkippedWithAWarning) {
  fs::remove(dir_ / "images" / "2.png");
  const RunResult r = run(dir_.string() + " --vision-only --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("2.png"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("skipped 1"), std::string::npos) << r.output;
}

TEST_F(OfflineCli, MissingCameraYamlNamesTheFile) {
  fs::remove(dir_ / "camera.yaml");
  const RunResult r = run(dir_.string() + " --vision-only --quiet");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("camera"), std::string::npos) << r.output;
}

TEST_F(OfflineCli, MalformedCsvNamesFileAndLine) {
  std::ofstream(dir_ / "frames.csv", std::ios::app)
      << "images/0.png,notanumber,0,0,0,0,0,0.5,0,0.5,0\n";
  const RunResult r = run(dir_.string() + " --vision-only --quiet");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("frames.csv:6"), std::string::npos) << r.output;
}

TEST_F(OfflineCli, UnknownStandardFieldIsNamed) {
  const RunResult r = run(dir_.string() + " --vision-only --quiet --standard nosuchfield");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("nosuchfield"), std::string::npos) << r.output;
}

TEST_F(OfflineCli, UnwritableOutputIsNamed) {
  std::ofstream(dir_ / "a_file") << "x";
  const std::string out = (dir_ / "a_file" / "out").string();
  const RunResult r = run(dir_.string() + " --vision-only --quiet -o " + out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(out), std::string::npos) << r.output;
}

TEST_F(OfflineCli, ImageOfTheWrongSizeIsAnError) {
  cv::imwrite((dir_ / "images" / "1.png").string(), cv::Mat(50, 60, CV_8UC3, cv::Scalar::all(90)));
  const RunResult r = run(dir_.string() + " --vision-only --quiet");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("1.png"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("60x50"), std::string::npos) << r.output;
}

TEST_F(OfflineCli, LaterModesSayTheyAreNotImplementedYet) {
  for (const std::string mode : {"--global-only", ""}) {
    const RunResult r = run(dir_.string() + " " + mode);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.output.find("not implemented yet"), std::string::npos) << r.output;
  }
}

TEST_F(OfflineCli, NoFolderIsAnError) {
  const RunResult r = run((dir_ / "nope").string() + " --vision-only");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("nope"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace houghloc
