#include "tools/recording/recording.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "field_models/standard_fields.h"
#include "vision/camera_presets.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

const char* kFramesHeader =
    "image,t_us,odom_x,odom_y,odom_theta,cam_x,cam_y,cam_z,cam_roll,cam_pitch,cam_yaw\n";

class RecordingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(HOUGHLOC_BINARY_DIR) / "test_tmp" / "recording" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    saveCameraYaml((dir_ / "camera.yaml").string(), cameraPreset("nao-top").intrinsics);
  }
  void write(const std::string& relative, const std::string& text) const {
    fs::create_directories((dir_ / relative).parent_path());
    std::ofstream(dir_ / relative) << text;
  }
  /// The RecordingError message of reading the folder ("" when it reads).
  std::string readError() const {
    try {
      readRecording(dir_.string());
    } catch (const RecordingError& e) {
      return e.what();
    }
    return "";
  }
  void expectError(const std::string& file_and_line, const std::string& what) const {
    const std::string message = readError();
    EXPECT_NE(message.find(file_and_line), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  }
  fs::path dir_;
};

/// A recording with awkward doubles (1/3, 0.1, tiny and huge values) in every file.
Recording makeRecording() {
  Recording r;
  const CameraPreset top = cameraPreset("nao-top");
  r.camera = top.intrinsics;
  r.cameras["bottom"] = cameraPreset("nao-bottom").intrinsics;
  for (int i = 0; i < 5; ++i) {
    FrameRecord f;
    f.image = "images/" + std::to_string(i) + ".png";
    f.t_us = 1'000'000'000'000 + 33'333 * i;
    f.odometry = Pose2(0.1 * i + 1.0 / 3.0, -2.0 / 7.0 * i, 3.14159 - 0.7 * i);
    if (i == 3) f.odometry = std::nullopt;  // a frame without odometry: empty fields
    f.robot_T_camera = top.robot_T_camera;
    f.robot_T_camera.yaw = 1e-300 * i - 0.123456789012345678;
    f.camera_id = i % 2 ? "bottom" : "";
    r.frames.push_back(f);
    r.ground_truth.push_back({f.t_us + 7, Pose2(1e5 / 3.0, -0.1 * i, -3.0 + i)});
  }
  r.hints.push_back({r.frames[1].t_us, "RESET_TO", Pose2(-4.5, 0.0, 1.0 / 3.0), 0.1, 0.2, 0.3});
  r.hints.push_back({r.frames[2].t_us, "OWN_HALF", std::nullopt, 0.0, 0.0, 0.0});
  r.field = makeStandardField("spl");
  r.visible.push_back({r.frames[0].t_us, "segments[3]", 1.0 / 3.0, 90.0});
  r.visible.push_back({r.frames[0].t_us, "arcs[0]", 2.5, 0.0});
  r.events.push_back({r.frames[3].t_us, "KIDNAP"});
  return r;
}

void expectIntrinsicsEqual(const CameraIntrinsics& a, const CameraIntrinsics& b) {
  EXPECT_EQ(a.image_width, b.image_width);
  EXPECT_EQ(a.image_height, b.image_height);
  for (int i = 0; i < 9; ++i) EXPECT_EQ(a.camera_matrix.val[i], b.camera_matrix.val[i]);
  EXPECT_EQ(a.distortion, b.distortion);
  EXPECT_EQ(a.model, b.model);
}

void expectPose2Equal(const Pose2& a, const Pose2& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.theta, b.theta);
}

TEST_F(RecordingTest, WriteReadRoundTripIsExact) {
  const Recording in = makeRecording();
  writeRecording(in, dir_.string());
  const Recording out = readRecording(dir_.string());
  ASSERT_TRUE(out.camera);
  expectIntrinsicsEqual(*out.camera, *in.camera);
  ASSERT_EQ(out.cameras.size(), 1u);
  expectIntrinsicsEqual(out.cameras.at("bottom"), in.cameras.at("bottom"));
  ASSERT_EQ(out.frames.size(), in.frames.size());
  for (std::size_t i = 0; i < in.frames.size(); ++i) {
    const FrameRecord &a = in.frames[i], &b = out.frames[i];
    EXPECT_EQ(a.image, b.image);
    EXPECT_EQ(a.t_us, b.t_us);
    ASSERT_EQ(a.odometry.has_value(), b.odometry.has_value());
    if (a.odometry) expectPose2Equal(*a.odometry, *b.odometry);
    EXPECT_EQ(a.robot_T_camera.x, b.robot_T_camera.x);
    EXPECT_EQ(a.robot_T_camera.z, b.robot_T_camera.z);
    EXPECT_EQ(a.robot_T_camera.pitch, b.robot_T_camera.pitch);
    EXPECT_EQ(a.robot_T_camera.yaw, b.robot_T_camera.yaw);
    EXPECT_EQ(a.camera_id, b.camera_id);
    expectIntrinsicsEqual(out.intrinsicsFor(b), i % 2 ? in.cameras.at("bottom") : *in.camera);
  }
  ASSERT_EQ(out.ground_truth.size(), in.ground_truth.size());
  for (std::size_t i = 0; i < in.ground_truth.size(); ++i) {
    EXPECT_EQ(out.ground_truth[i].t_us, in.ground_truth[i].t_us);
    expectPose2Equal(out.ground_truth[i].field_T_robot, in.ground_truth[i].field_T_robot);
  }
  ASSERT_EQ(out.hints.size(), 2u);
  EXPECT_EQ(out.hints[0].kind, "RESET_TO");
  ASSERT_TRUE(out.hints[0].pose);
  expectPose2Equal(*out.hints[0].pose, *in.hints[0].pose);
  EXPECT_EQ(out.hints[0].sigma_y, 0.2);
  EXPECT_EQ(out.hints[1].kind, "OWN_HALF");
  EXPECT_FALSE(out.hints[1].pose);
  ASSERT_TRUE(out.field);
  EXPECT_EQ(out.field->segments.size(), in.field->segments.size());
  EXPECT_EQ(out.field->line_width, in.field->line_width);
  ASSERT_EQ(out.visible.size(), 2u);
  EXPECT_EQ(out.visible[0].feature, "segments[3]");
  EXPECT_EQ(out.visible[0].visible_length_m, 1.0 / 3.0);
  EXPECT_EQ(out.visible[1].direction_deg, 0.0);
  ASSERT_EQ(out.events.size(), 1u);
  EXPECT_EQ(out.events[0].event, "KIDNAP");
  EXPECT_EQ(out.events[0].t_us, in.frames[3].t_us);
  // Writing what was read gives the same bytes.
  const fs::path again = dir_ / "again";
  writeRecording(out, again.string());
  for (const char* file : {"frames.csv", "groundtruth.csv", "hints.csv", "truth/visible.csv"}) {
    std::ifstream a(dir_ / file), b(again / file);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(a), {}),
              std::string(std::istreambuf_iterator<char>(b), {}))
        << file;
  }
}

TEST_F(RecordingTest, RandomDoublesRoundTripExactly) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0), unit(-1.0, 1.0);
  Recording in;
  in.camera = cameraPreset("adult").intrinsics;
  for (int i = 0; i < 2000; ++i) {
    const double x = unit(rng) * std::pow(10.0, exponent(rng));
    const double y = unit(rng) * 10.0;
    in.ground_truth.push_back({i, Pose2(x, y, unit(rng) * 3.0)});
  }
  writeRecording(in, dir_.string());
  std::ofstream(dir_ / "frames.csv") << kFramesHeader;
  const Recording out = readRecording(dir_.string());
  ASSERT_EQ(out.ground_truth.size(), in.ground_truth.size());
  for (std::size_t i = 0; i < in.ground_truth.size(); ++i) {
    expectPose2Equal(out.ground_truth[i].field_T_robot, in.ground_truth[i].field_T_robot);
  }
}

TEST_F(RecordingTest, CommentsBlankLinesAndExtraColumnsAreAccepted) {
  write("frames.csv",
        "# recorded on the field\n"
        "note,cam_yaw,cam_pitch,cam_roll,cam_z,cam_y,cam_x,odom_theta,odom_y,odom_x,t_us,image\n"
        "  # an indented comment\n"
        "\n"
        "hello,0.1,0.2,0.3,0.5,0,0.05,1.5,2,1,100,a.png\r\n"
        "world,0,0,0,0.5,0,0,0,0,0,200,b.png\n");
  write("groundtruth.csv", "t_us,x,y,theta,quality\n#x\n100, 1.5 ,2,0.25,good\n");
  const Recording r = readRecording(dir_.string());
  ASSERT_EQ(r.frames.size(), 2u);
  EXPECT_EQ(r.frames[0].image, "a.png");
  EXPECT_EQ(r.frames[0].t_us, 100);
  ASSERT_TRUE(r.frames[0].odometry);
  EXPECT_EQ(r.frames[0].odometry->x, 1.0);
  EXPECT_EQ(r.frames[0].odometry->y, 2.0);
  EXPECT_EQ(r.frames[0].odometry->theta, 1.5);
  EXPECT_EQ(r.frames[0].robot_T_camera.yaw, 0.1);
  EXPECT_EQ(r.frames[0].robot_T_camera.x, 0.05);
  EXPECT_TRUE(r.frames[0].camera_id.empty());
  ASSERT_EQ(r.ground_truth.size(), 1u);
  EXPECT_EQ(r.ground_truth[0].field_T_robot.x, 1.5);
  EXPECT_FALSE(r.field);
  EXPECT_TRUE(r.hints.empty());
}

TEST_F(RecordingTest, EmptyOdometryFieldsMeanNoOdometry) {
  write("frames.csv", std::string(kFramesHeader) + "a.png,1,0.5,-1,0.25,0,0,0.5,0,0,0\n" +
                          "b.png,2,,,,0,0,0.5,0,0,0\n" + "c.png,3, , ,,0,0,0.5,0,0,0\n" +
                          "d.png,4,0,0,0,0,0,0.5,0,0,0\n");
  const Recording r = readRecording(dir_.string());
  ASSERT_EQ(r.frames.size(), 4u);
  ASSERT_TRUE(r.frames[0].odometry);
  EXPECT_EQ(r.frames[0].odometry->x, 0.5);
  EXPECT_EQ(r.frames[0].odometry->y, -1.0);
  EXPECT_EQ(r.frames[0].odometry->theta, 0.25);
  EXPECT_FALSE(r.frames[1].odometry);
  EXPECT_FALSE(r.frames[2].odometry);  // fields of spaces are empty too
  EXPECT_EQ(r.frames[2].robot_T_camera.z, 0.5);
  ASSERT_TRUE(r.frames[3].odometry);
  EXPECT_EQ(r.frames[3].odometry->x, 0.0);
}

TEST_F(RecordingTest, PartlyEmptyOdometryNamesFileLineAndColumn) {
  write("frames.csv", std::string(kFramesHeader) + "a.png,1,0,0,0,0,0,0.5,0,0,0\n" +
                          "b.png,2,1,,0,0,0,0.5,0,0,0\n");
  expectError("frames.csv:3:", "column 'odom_y' is empty");
  write("frames.csv", std::string(kFramesHeader) + "a.png,1,,,0.5,0,0,0.5,0,0,0\n");
  expectError("frames.csv:2:", "column 'odom_x' is empty");
  write("frames.csv", std::string(kFramesHeader) + "a.png,1,1,2,,0,0,0.5,0,0,0\n");
  expectError("frames.csv:2:", "column 'odom_theta' is empty");
  // The camera pose has no such rule: an empty field there is not a number.
  write("frames.csv", std::string(kFramesHeader) + "a.png,1,,,,0,0,0.5,0,,0\n");
  expectError("frames.csv:2:", "'cam_pitch': '' is not a finite number");
}

TEST_F(RecordingTest, MalformedRowNamesFileAndLine) {
  write("frames.csv", std::string(kFramesHeader) + "a.png,1,0,0,0,0,0,0.5,0,0,0\n" +
                          "b.png,2,0,0,0,0,0,0.5,0,0\n");
  expectError("frames.csv:3:", "10 fields, the header has 11");
}

TEST_F(RecordingTest, NonNumericFieldNamesFileLineAndColumn) {
  write("frames.csv",
        std::string("# comment\n") + kFramesHeader + "a.png,1,0,0,0,0,0,0.5,0,zero,0\n");
  expectError("frames.csv:3:", "'cam_pitch': 'zero' is not a finite number");
  write("frames.csv", std::string(kFramesHeader) + "a.png,1.5,0,0,0,0,0,0.5,0,0,0\n");
  expectError("frames.csv:2:", "'t_us': '1.5' is not an integer");
  write("frames.csv", std::string(kFramesHeader) + "a.png,1,nan,0,0,0,0,0.5,0,0,0\n");
  expectError("frames.csv:2:", "'odom_x'");
}

TEST_F(RecordingTest, TimeGoingBackwardsIsAnError) {
  write("frames.csv", std::string(kFramesHeader) + "a.png,10,0,0,0,0,0,0.5,0,0,0\n" +
                          "b.png,10,0,0,0,0,0,0.5,0,0,0\n" + "c.png,9,0,0,0,0,0,0.5,0,0,0\n");
  expectError("frames.csv:4:", "t_us goes backwards (9 after 10)");
  write("frames.csv", std::string(kFramesHeader) + "a.png,10,0,0,0,0,0,0.5,0,0,0\n");
  write("groundtruth.csv", "t_us,x,y,theta\n5,0,0,0\n4,0,0,0\n");
  expectError("groundtruth.csv:3:", "backwards");
}

TEST_F(RecordingTest, HintsUnknownKindAndPartialPoses) {
  write("frames.csv", std::string(kFramesHeader) + "a.png,10,0,0,0,0,0,0.5,0,0,0\n");
  const std::string header = "t_us,kind,x,y,theta,sigma_x,sigma_y,sigma_theta\n";
  write("hints.csv", header + "10,MIRROR,,,,,,\n20,ADD,1,2,3,0.1,0.1,0.1\n");
  const Recording r = readRecording(dir_.string());
  ASSERT_EQ(r.hints.size(), 2u);
  EXPECT_FALSE(r.hints[0].pose);
  EXPECT_EQ(r.hints[0].sigma_x, 0.0);
  ASSERT_TRUE(r.hints[1].pose);
  EXPECT_EQ(r.hints[1].pose->y, 2.0);
  write("hints.csv", header + "10,MIRROR,,,,,,\n20,TELEPORT,1,2,3,0.1,0.1,0.1\n");
  expectError("hints.csv:3:", "unknown hint kind 'TELEPORT'");
  write("hints.csv", header + "10,ADD,1,,3,0.1,0.1,0.1\n");
  expectError("hints.csv:2:", "all given or all empty");
  write("hints.csv", "t_us,kind,x,y\n10,ADD,1,2\n");
  expectError("hints.csv:1:", "missing column 'theta'");
}

TEST_F(RecordingTest, TruthFilesAreChecked) {
  write("frames.csv", std::string(kFramesHeader) + "a.png,10,0,0,0,0,0,0.5,0,0,0\n");
  write("truth/events.csv", "t_us,event\n10,KIDNAP\n20,EXPLOSION\n");
  expectError("events.csv:3:", "unknown event 'EXPLOSION'");
  write("truth/events.csv", "t_us,event\n10,FALL_START\n20,FALL_END\n");
  write("truth/visible.csv", "t_us,feature,visible_length_m,direction_deg\n10,arcs[0],long,0\n");
  expectError("visible.csv:2:", "'visible_length_m'");
}

TEST_F(RecordingTest, MissingFilesAreNamed) {
  expectError("frames.csv", "cannot open");
  write("frames.csv", "# only a comment\n");
  expectError("frames.csv:1:", "missing header");
  write("frames.csv", std::string(kFramesHeader) + "a.png,10,0,0,0,0,0,0.5,0,0,0\n");
  fs::remove(dir_ / "camera.yaml");
  expectError("frames.csv:2:", "camera.yaml not found");
  write("frames.csv",
        "image,t_us,odom_x,odom_y,odom_theta,cam_x,cam_y,cam_z,cam_roll,cam_pitch,"
        "cam_yaw,camera\na.png,10,0,0,0,0,0,0.5,0,0,0,left\n");
  expectError("frames.csv:2:", "cameras/left.yaml not found");
  saveCameraYaml((dir_ / "cameras_left.yaml").string(), cameraPreset("adult").intrinsics);
  fs::create_directories(dir_ / "cameras");
  fs::rename(dir_ / "cameras_left.yaml", dir_ / "cameras" / "left.yaml");
  const Recording r = readRecording(dir_.string());
  EXPECT_EQ(r.intrinsicsFor(r.frames[0]).image_width, 1280);
  EXPECT_THROW(r.intrinsicsFor(FrameRecord{}), RecordingError);
  write("cameras/left.yaml", "%YAML:1.0\n---\nimage_width: 640\n");
  expectError("left.yaml", "'image_height'");
  fs::remove(dir_ / "cameras" / "left.yaml");
  write("frames.csv", std::string(kFramesHeader));
  expectError("camera.yaml", "missing camera");
  EXPECT_THROW(readRecording((dir_ / "nowhere").string()), RecordingError);
}

TEST_F(RecordingTest, BadFieldYamlIsReported) {
  write("frames.csv", std::string(kFramesHeader) + "a.png,10,0,0,0,0,0,0.5,0,0,0\n");
  write("field.yaml", "%YAML:1.0\n---\nname: broken\nsegments:\n   - [ 1, 2, 3 ]\n");
  expectError("field.yaml", "field_length");
}

TEST_F(RecordingTest, WriterRefusesFieldsItCouldNotReadBack) {
  Recording r = makeRecording();
  r.frames[0].image = "a,b.png";
  EXPECT_THROW(writeRecording(r, (dir_ / "w1").string()), RecordingError);
  r = makeRecording();
  r.ground_truth[0].field_T_robot.x = std::nan("");
  EXPECT_THROW(writeRecording(r, (dir_ / "w2").string()), RecordingError);
}

}  // namespace
}  // namespace houghloc
