#pragma once
// A tiny recorded folder and a way to run houghloc-offline on it, shared by the CLI tests.
#include <gtest/gtest.h>
#include <unistd.h>

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

namespace fs = std::filesystem;

struct RunResult {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr
};

inline RunResult run(const std::string& args) {
  const std::string command = std::string(HOUGHLOC_OFFLINE_EXE) + " " + args + " 2>&1";
  RunResult result;
  FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe)) result.output += buffer.data();
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

inline std::string readFile(const fs::path& path) {
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
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));  // the process id: test runs of other trees at once
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

}  // namespace houghloc
