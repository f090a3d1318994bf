// houghloc-offline as a user runs it: exit codes and messages for good and bad folders.
#include "tests/tools/offline/offline_cli_fixture.h"

namespace houghloc {
namespace {

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

TEST_F(OfflineCli, NoFolderIsAnError) {
  const RunResult r = run((dir_ / "nope").string() + " --vision-only");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("nope"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace houghloc
