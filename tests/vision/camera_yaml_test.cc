#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "vision/camera_model.h"
#include "vision/camera_presets.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

class CameraYamlTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(HOUGHLOC_BINARY_DIR) / "test_tmp" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  std::string write(const std::string& text) const {
    const std::string path = (dir_ / "camera.yaml").string();
    std::ofstream(path) << text;
    return path;
  }
  /// The message of the runtime_error loading `text` throws ("" when it does not throw).
  std::string loadError(const std::string& text) const {
    const std::string path = write(text);
    try {
      loadCameraYaml(path);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

const char* kValidHeader =
    "%YAML:1.0\n---\nimage_width: 640\nimage_height: 480\n"
    "camera_matrix: !!opencv-matrix\n  rows: 3\n  cols: 3\n  dt: d\n"
    "  data: [ 500., 0., 320., 0., 500., 240., 0., 0., 1. ]\n";

TEST_F(CameraYamlTest, RoundTripIsExactForEveryPreset) {
  for (const std::string& name : cameraPresetNames()) {
    CameraIntrinsics in = cameraPreset(name).intrinsics;
    in.camera_matrix(0, 0) += 1.0 / 3.0;  // digits a short format would lose
    in.distortion[0] += 1e-17 + 1.0 / 7.0 * 1e-3;
    const std::string path = (dir_ / (name + ".yaml")).string();
    saveCameraYaml(path, in);
    const CameraIntrinsics out = loadCameraYaml(path);
    EXPECT_EQ(out.image_width, in.image_width);
    EXPECT_EQ(out.image_height, in.image_height);
    for (int i = 0; i < 9; ++i) EXPECT_EQ(out.camera_matrix.val[i], in.camera_matrix.val[i]);
    EXPECT_EQ(out.distortion, in.distortion);
    EXPECT_EQ(out.model, in.model);
  }
}

TEST_F(CameraYamlTest, IdealLensRoundTrips) {
  CameraIntrinsics in;
  in.camera_matrix = cv::Matx33d(400, 0, 319.5, 0, 410, 239.5, 0, 0, 1);
  const std::string path = (dir_ / "ideal.yaml").string();
  saveCameraYaml(path, in);
  const CameraIntrinsics out = loadCameraYaml(path);
  EXPECT_TRUE(out.distortion.empty());
  EXPECT_EQ(out.camera_matrix(1, 1), 410.0);
}

TEST_F(CameraYamlTest, AcceptsPlainSequencesAndMissingModel) {
  const CameraIntrinsics in = loadCameraYaml(
      write(std::string(kValidHeader) + "distortion_coefficients: [ -0.1, 0.01, 0, 0, 0 ]\n"));
  EXPECT_EQ(in.model, DistortionModel::kPinhole);
  ASSERT_EQ(in.distortion.size(), 5u);
  EXPECT_EQ(in.distortion[0], -0.1);
}

TEST_F(CameraYamlTest, ErrorsNameFileAndKey) {
  auto expectError = [&](const std::string& text, const std::string& key) {
    const std::string message = loadError(text);
    EXPECT_NE(message.find("camera.yaml"), std::string::npos) << message;
    EXPECT_NE(message.find(key), std::string::npos) << message;
  };
  expectError("%YAML:1.0\n---\nimage_height: 480\n", "'image_width'");
  expectError("%YAML:1.0\n---\nimage_width: wide\nimage_height: 480\n", "'image_width'");
  expectError("%YAML:1.0\n---\nimage_width: 640\nimage_height: -4\n", "'image_height'");
  expectError("%YAML:1.0\n---\nimage_width: 640\nimage_height: 480\n", "'camera_matrix'");
  expectError("%YAML:1.0\n---\nimage_width: 640\nimage_height: 480\ncamera_matrix: [1, 2]\n",
              "'camera_matrix'");
  expectError(std::string(kValidHeader) + "distortion_coefficients: [ 0.1, 0.2, 0.3 ]\n",
              "'distortion_coefficients'");
  expectError(std::string(kValidHeader) + "distortion_coefficients: [ 0.1, x ]\n",
              "'distortion_coefficients'");
  expectError(std::string(kValidHeader) + "model: kannala\n", "'model'");
  expectError(std::string(kValidHeader) +
                  "model: fisheye\ndistortion_coefficients: [ 0.1, 0.0, 0.0, 0.0, 0.0 ]\n",
              "'distortion_coefficients'");
  expectError("%YAML:1.0\n---\nimage_width: [640\n", "camera.yaml");
  const std::string missing = (dir_ / "none.yaml").string();
  try {
    loadCameraYaml(missing);
    ADD_FAILURE() << "no error for a missing file";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("none.yaml"), std::string::npos);
  }
}

}  // namespace
}  // namespace houghloc
