// houghloc-offline end to end on rendered recordings (seeds never used for tuning): the accuracy
// targets of issue 7 with fixed thresholds, the documented outputs, --evaluate-only and
// --threads 2 reproducing a run exactly, and a folder with a corrupt image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "offline_cli_fixture.h"

namespace houghloc {
namespace {

// Issue 7: on frames with two directions in view, the hypotheses contain a pose correct up to
// symmetry (0.10 m, 3 deg) in >= 90% of the frames and the best pose is in >= 80%.
constexpr double kMinCorrectAnyRate = 0.90;
constexpr double kMinBestCorrectRate = 0.80;

const fs::path kFixtures = HOUGHLOC_OFFLINE_FIXTURES;

std::string firstLine(const fs::path& path) {
  const std::string text = readFile(path);
  return text.substr(0, text.find('\n'));
}

fs::path outDir(const std::string& name) {
  // In the build tree, so that runs from several build trees never share a folder.
  const fs::path dir = fs::path(HOUGHLOC_OFFLINE_WORK) / name;
  fs::remove_all(dir);
  return dir;
}

class OfflineAccuracy : public ::testing::TestWithParam<std::string> {};

TEST_P(OfflineAccuracy, FullRunMeetsTheTargetsAndIsReproducible) {
  const fs::path folder = kFixtures / GetParam();
  const fs::path out = outDir(GetParam() + "_full");
  const RunResult r = run(folder.string() + " --quiet -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::printf("%s\n", r.output.c_str());

  EXPECT_EQ(firstLine(out / "poses.csv"),
            "t_us,x,y,theta,var_x,var_y,var_theta,weight,num_hypotheses,status,twin_weight");
  EXPECT_EQ(firstLine(out / "hypotheses.csv"),
            "t_us,rank,x,y,theta,var_x,var_y,var_theta,cov_xy,cov_xtheta,cov_ytheta,weight");
  EXPECT_EQ(
      firstLine(out / "timing.csv").rfind("t_us,vision_ms,localization_ms,global_ms,points", 0),
      0u);
  EXPECT_TRUE(fs::exists(out / "trajectory.png"));

  const std::string metrics_text = readFile(out / "metrics.json");
  const nlohmann::json metrics = nlohmann::json::parse(metrics_text);
  ASSERT_TRUE(metrics.contains("tracking")) << metrics_text;
  const nlohmann::json& tracking = metrics["tracking"];
  ASSERT_GT(tracking["frames_two_directions"].get<int>(), 50) << metrics_text;
  const double any = tracking["two_direction_correct_any_rate"].get<double>();
  const double best = tracking["two_direction_best_correct_rate"].get<double>();
  std::printf("%s: two directions: any correct %.3f, best correct %.3f\n", GetParam().c_str(), any,
              best);
  EXPECT_GE(any, kMinCorrectAnyRate) << metrics_text;
  EXPECT_GE(best, kMinBestCorrectRate) << metrics_text;

  // --evaluate-only rewrites metrics.json from poses.csv and hypotheses.csv: byte for byte.
  fs::remove(out / "metrics.json");
  const RunResult e = run(folder.string() + " --evaluate-only -o " + out.string());
  ASSERT_EQ(e.exit_code, 0) << e.output;
  EXPECT_EQ(readFile(out / "metrics.json"), metrics_text);

  // Vision of frame k+1 overlapping localization of frame k changes nothing.
  const fs::path out2 = outDir(GetParam() + "_threads");
  const RunResult t = run(folder.string() + " --quiet --threads 2 -o " + out2.string());
  ASSERT_EQ(t.exit_code, 0) << t.output;
  for (const char* file : {"poses.csv", "hypotheses.csv", "metrics.json"}) {
    EXPECT_TRUE(readFile(out / file) == readFile(out2 / file)) << file;
  }
}

TEST_P(OfflineAccuracy, GlobalOnlyRunIsScoredAndReevaluatedExactly) {
  const fs::path folder = kFixtures / GetParam();
  const fs::path out = outDir(GetParam() + "_global");
  const RunResult r = run(folder.string() + " --global-only --quiet -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::printf("%s\n", r.output.c_str());
  const std::string metrics_text = readFile(out / "metrics.json");
  const nlohmann::json metrics = nlohmann::json::parse(metrics_text);
  ASSERT_TRUE(metrics.contains("global")) << metrics_text;
  EXPECT_FALSE(metrics.contains("tracking")) << metrics_text;
  fs::remove(out / "metrics.json");
  const RunResult e = run(folder.string() + " --global-only --evaluate-only -o " + out.string());
  ASSERT_EQ(e.exit_code, 0) << e.output;
  EXPECT_EQ(readFile(out / "metrics.json"), metrics_text);
}

INSTANTIATE_TEST_SUITE_P(Renders, OfflineAccuracy,
                         ::testing::Values("spl_nao-top_walk", "kid_kid-wide_walk",
                                           "spl_kid-wide_walk", "kid_nao-top_walk"));

/// The printed "camera correction at the end (camera): roll R deg, pitch P deg" (deg), or NaN.
std::pair<double, double> finalCorrection(const std::string& output, const std::string& camera) {
  const std::string key = "camera correction at the end (" + camera + "):";
  const size_t at = output.find(key);
  double roll = std::nan(""), pitch = std::nan("");
  if (at != std::string::npos) {
    std::sscanf(output.c_str() + at + key.size(), " roll %lf deg, pitch %lf", &roll, &pitch);
  }
  return {roll, pitch};
}

/// A NAO walk, both cameras 2 / 1 deg off. With a corrector per camera the top one is corrected,
/// the bottom one never (too little in view). With one corrector for both cameras both end with
/// the whole error corrected, and tracking stays within 10 cm and 3 deg on >= 85 % of the frames
/// (measured 89.3 %: frames 14-24, before the first correction, are off; with the corrector's
/// early 4 deg runaway, since fixed, 57.7 %).
TEST(OfflineNaoPoseError, SharedCorrectorCorrectsBothCameras) {
  const fs::path folder = kFixtures / "spl_nao_walk_pose-error";
  const fs::path own = outDir("nao_pose_error_own");
  const RunResult a = run(folder.string() + " --quiet -o " + own.string());
  ASSERT_EQ(a.exit_code, 0) << a.output;
  std::printf("%s\n", a.output.c_str());
  EXPECT_EQ(finalCorrection(a.output, "nao-bottom"), std::make_pair(0.0, 0.0)) << a.output;
  const auto [top_roll, top_pitch] = finalCorrection(a.output, "nao-top");
  EXPECT_NEAR(top_roll, -1.0, 0.05) << a.output;
  EXPECT_NEAR(top_pitch, -2.0, 0.05) << a.output;

  const fs::path shared = outDir("nao_pose_error_shared");
  fs::create_directories(shared);
  std::ofstream(shared / "shared.yaml") << "vision:\n  pose_correction:\n"
                                        << "    shared_between_cameras: 1\n";
  const RunResult b = run(folder.string() + " --quiet -o " + shared.string() + " --config " +
                          (shared / "shared.yaml").string());
  ASSERT_EQ(b.exit_code, 0) << b.output;
  std::printf("%s\n", b.output.c_str());
  for (const char* camera : {"nao-top", "nao-bottom"}) {
    const auto [roll, pitch] = finalCorrection(b.output, camera);
    EXPECT_NEAR(roll, -1.0, 0.05) << camera << "\n" << b.output;
    EXPECT_NEAR(pitch, -2.0, 0.05) << camera << "\n" << b.output;
  }
  const nlohmann::json metrics = nlohmann::json::parse(readFile(shared / "metrics.json"));
  EXPECT_GE(metrics["tracking"]["correct_rate"].get<double>(), 0.85) << metrics.dump();
}

/// The first 40 frames of a rendered folder with one image replaced by garbage.
TEST(OfflineCorruptImage, RunCompletesAndCountsTheFrame) {
  const fs::path source = kFixtures / "spl_nao-top_walk";
  const fs::path folder = outDir("corrupt");
  fs::create_directories(folder / "images");
  for (const char* file : {"camera.yaml", "field.yaml", "groundtruth.csv"}) {
    fs::copy_file(source / file, folder / file);
  }
  std::ifstream frames_in(source / "frames.csv");
  std::ofstream frames_out(folder / "frames.csv");
  std::string line, corrupted;
  for (int row = -1; row < 40 && std::getline(frames_in, line); ++row) {
    frames_out << line << "\n";
    if (row < 0) continue;
    const std::string image = line.substr(0, line.find(','));
    if (row == 20) {
      std::ofstream(folder / image, std::ios::binary) << "\x89PNG\r\n\x1a\nnot really";
      corrupted = fs::path(image).filename().string();
    } else {
      fs::copy_file(source / image, folder / image);
    }
  }
  frames_out.close();
  const RunResult r = run(folder.string() + " --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(corrupted), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("skipped 1"), std::string::npos) << r.output;
  const std::string poses = readFile(folder / "houghloc" / "poses.csv");
  EXPECT_EQ(std::count(poses.begin(), poses.end(), '\n'), 41);
}

}  // namespace
}  // namespace houghloc
