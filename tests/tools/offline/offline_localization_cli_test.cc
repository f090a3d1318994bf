// houghloc-offline's localization modes (--global-only, the full mode, --evaluate-only,
// --config/--print-config, --video) as a user runs them: outputs, exit codes and messages.
#include "tests/tools/offline/offline_cli_fixture.h"

namespace houghloc {
namespace {

const char* const kPosesHeader =
    "t_us,x,y,theta,var_x,var_y,var_theta,weight,num_hypotheses,status,twin_weight";
const char* const kHypothesesHeader =
    "t_us,rank,x,y,theta,var_x,var_y,var_theta,cov_xy,cov_xtheta,cov_ytheta,weight";

/// The two localization modes; the tiny folder has no field.yaml, so they get --standard spl.
const std::vector<std::string> kModes = {"--global-only --standard spl", "--standard spl"};

std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

int dataLines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n')) - 1;
}

void rewriteFramesCsv(const fs::path& dir, const std::function<void(std::string*)>& edit) {
  std::string text = readFile(dir / "frames.csv");
  edit(&text);
  std::ofstream(dir / "frames.csv") << text;
}

TEST_F(OfflineCli, LocalizationModesWriteEveryOutputWithTheDesignHeaders) {
  for (const std::string& mode : kModes) {
    const fs::path out = dir_ / "out";
    fs::remove_all(out);
    const RunResult r = run(dir_.string() + " " + mode + " --quiet --points -o " + out.string());
    ASSERT_EQ(r.exit_code, 0) << mode << "\n" << r.output;
    const std::string poses = readFile(out / "poses.csv");
    EXPECT_EQ(firstLine(poses), kPosesHeader) << mode;
    EXPECT_EQ(dataLines(poses), 4) << mode << "\n" << poses;
    EXPECT_EQ(firstLine(readFile(out / "hypotheses.csv")), kHypothesesHeader) << mode;
    EXPECT_EQ(firstLine(readFile(out / "points.csv")), "t_us,u,v,x_robot,y_robot") << mode;
    const std::string timing = readFile(out / "timing.csv");
    EXPECT_EQ(timing.rfind("t_us,vision_ms,localization_ms,global_ms,points", 0), 0u) << timing;
    EXPECT_EQ(dataLines(timing), 4) << mode;
    EXPECT_TRUE(fs::exists(out / "trajectory.png")) << mode;
    EXPECT_NE(r.output.find("processed 4, skipped 0"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("localization"), std::string::npos) << r.output;
  }
}

TEST_F(OfflineCli, OverlayAndVideoShowEveryFrame) {
  const fs::path video = dir_ / "overlay.avi";
  const RunResult r =
      run(dir_.string() + " --standard spl --quiet --overlay --video " + video.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (int i = 0; i < 4; ++i) {
    const cv::Mat overlay =
        cv::imread((dir_ / "houghloc" / "overlay" / (std::to_string(i) + ".png")).string());
    ASSERT_FALSE(overlay.empty()) << i;
    EXPECT_EQ(overlay.size(), cv::Size(160, 120));
  }
  EXPECT_GT(fs::file_size(video), 1000u);
}

TEST_F(OfflineCli, VideoThatCannotBeWrittenIsNamed) {
  const std::string video = (dir_ / "no" / "such" / "dir" / "v.avi").string();
  const RunResult r = run(dir_.string() + " --standard spl --quiet --video " + video);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(video), std::string::npos) << r.output;
}

TEST_F(OfflineCli, CorruptImageIsSkippedAndTheRunCompletes) {
  std::ofstream(dir_ / "images" / "2.png", std::ios::binary) << "\x89PNG\r\n\x1a\n garbage";
  for (const std::string& mode : kModes) {
    const RunResult r = run(dir_.string() + " " + mode);
    EXPECT_EQ(r.exit_code, 0) << mode << "\n" << r.output;
    EXPECT_NE(r.output.find("warning"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("2.png"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("skipped 1"), std::string::npos) << r.output;
    // The skipped frame still has its poses.csv row (prediction only).
    EXPECT_EQ(dataLines(readFile(dir_ / "houghloc" / "poses.csv")), 4) << mode;
  }
}

TEST_F(OfflineCli, BadInputIsNamedInEveryMode) {
  struct Case {
    std::string name;
    std::function<void()> damage;
    std::string extra_args;
    std::string expected;  ///< in the message
  };
  const std::vector<Case> cases = {
      {"missing camera.yaml", [&] { fs::remove(dir_ / "camera.yaml"); }, "", "camera.yaml"},
      {"non-numeric field",
       [&] {
         rewriteFramesCsv(dir_, [](std::string* t) {
           t->replace(t->find("\nimages/1.png,100000,"), 20, "\nimages/1.png,1e5x,");
         });
       },
       "", "frames.csv:3"},
      {"malformed row",
       [&] { std::ofstream(dir_ / "frames.csv", std::ios::app) << "images/0.png,400000,0\n"; }, "",
       "frames.csv:6"},
      {"times going backwards",
       [&] {
         rewriteFramesCsv(dir_, [](std::string* t) {
           t->replace(t->find("\nimages/3.png,300000,"), 20, "\nimages/3.png,50000,");
         });
       },
       "", "frames.csv:5"},
      {"unknown hint kind",
       [&] {
         std::ofstream(dir_ / "hints.csv")
             << "t_us,kind,x,y,theta,sigma_x,sigma_y,sigma_theta\n0,TELEPORT,,,,,,\n";
       },
       "", "hints.csv:2"},
      {"RESET_TO without a pose",
       [&] {
         std::ofstream(dir_ / "hints.csv")
             << "t_us,kind,x,y,theta,sigma_x,sigma_y,sigma_theta\n0,RESET_TO,,,,,,\n";
       },
       "", "hints.csv"},
      {"unknown standard", [] {}, " --standard nosuchfield", "nosuchfield"},
      {"unwritable output", [&] { std::ofstream(dir_ / "a_file") << "x"; },
       " -o " + (dir_ / "a_file" / "out").string(), (dir_ / "a_file" / "out").string()},
      {"bad config key",
       [&] { std::ofstream(dir_ / "bad.yaml") << "%YAML:1.0\nvision:\n  nosuchkey: 1\n"; },
       " --config " + (dir_ / "bad.yaml").string(), "bad.yaml"},
  };
  for (const std::string& mode : {std::string("--global-only"), std::string("")}) {
    for (const Case& c : cases) {
      SetUp();  // a fresh folder
      c.damage();
      const std::string field =
          c.extra_args.find("--standard") == std::string::npos ? " --standard spl" : "";
      const RunResult r = run(dir_.string() + " " + mode + field + c.extra_args + " --quiet");
      EXPECT_EQ(r.exit_code, 2) << mode << ": " << c.name << "\n" << r.output;
      EXPECT_NE(r.output.find(c.expected), std::string::npos) << mode << ": " << c.name << "\n"
                                                              << r.output;
    }
  }
}

TEST_F(OfflineCli, LocalizationModesNeedAField) {
  const RunResult r = run(dir_.string() + " --quiet");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--standard"), std::string::npos) << r.output;
}

TEST_F(OfflineCli, EvaluateOnlyWithoutAnEarlierRunNamesTheMissingFile) {
  const RunResult r = run(dir_.string() + " --standard spl --evaluate-only");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(r.output.find("houghloc/poses.csv") != std::string::npos ||
              r.output.find("houghloc/hypotheses.csv") != std::string::npos)
      << r.output;
}

TEST_F(OfflineCli, PrintConfigWritesEverySectionAndReadsBack) {
  const RunResult printed = run("--print-config");
  ASSERT_EQ(printed.exit_code, 0) << printed.output;
  for (const char* section : {"\nvision:", "\nglobal:", "\ntracker:", "\nlocalizer:"}) {
    EXPECT_NE(printed.output.find(section), std::string::npos) << section;
  }
  std::ofstream(dir_ / "defaults.yaml") << printed.output;
  const RunResult a = run(dir_.string() + " --standard spl --quiet -o " + (dir_ / "a").string());
  const RunResult b = run(dir_.string() + " --standard spl --quiet -o " + (dir_ / "b").string() +
                          " --config " + (dir_ / "defaults.yaml").string());
  ASSERT_EQ(a.exit_code, 0) << a.output;
  ASSERT_EQ(b.exit_code, 0) << b.output;
  EXPECT_EQ(readFile(dir_ / "a" / "hypotheses.csv"), readFile(dir_ / "b" / "hypotheses.csv"));
}

TEST_F(OfflineCli, ConfigChangesTheLocalizer) {
  // At most one global hypothesis: --global-only must never write a rank 1 row. A hand-written
  // file may leave out OpenCV's "%YAML:1.0" line.
  for (const std::string header : {"%YAML:1.0\n", ""}) {
    std::ofstream(dir_ / "one.yaml") << header << "global:\n  hypotheses:\n    max_hypotheses: 1\n";
    const RunResult r = run(dir_.string() + " --global-only --standard spl --quiet --config " +
                            (dir_ / "one.yaml").string());
    ASSERT_EQ(r.exit_code, 0) << header << r.output;
    EXPECT_EQ(readFile(dir_ / "houghloc" / "hypotheses.csv").find(",1,"), std::string::npos)
        << header;
  }
}

TEST_F(OfflineCli, ResetToHintPlacesTheEstimate) {
  std::ofstream(dir_ / "hints.csv") << "t_us,kind,x,y,theta,sigma_x,sigma_y,sigma_theta\n"
                                    << "0,RESET_TO,-2.5,1.5,0.5,0.05,0.05,0.02\n";
  const RunResult r = run(dir_.string() + " --standard spl --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string poses = readFile(dir_ / "houghloc" / "poses.csv");
  const std::string first = poses.substr(poses.find('\n') + 1);
  double t = 0, x = 0, y = 0, theta = 0;
  ASSERT_EQ(std::sscanf(first.c_str(), "%lf,%lf,%lf,%lf", &t, &x, &y, &theta), 4) << poses;
  EXPECT_NEAR(x, -2.5, 0.3) << poses;
  EXPECT_NEAR(y, 1.5, 0.3) << poses;
  EXPECT_NEAR(theta, 0.5, 0.1) << poses;
}

TEST_F(OfflineCli, TwoThreadsGiveIdenticalResults) {
  for (const std::string& mode : kModes) {
    const RunResult a = run(dir_.string() + " " + mode + " --quiet -o " + (dir_ / "a").string());
    const RunResult b =
        run(dir_.string() + " " + mode + " --quiet --threads 2 -o " + (dir_ / "b").string());
    ASSERT_EQ(a.exit_code, 0) << a.output;
    ASSERT_EQ(b.exit_code, 0) << b.output;
    for (const char* file : {"poses.csv", "hypotheses.csv"}) {
      EXPECT_EQ(readFile(dir_ / "a" / file), readFile(dir_ / "b" / file)) << mode << " " << file;
    }
  }
}

}  // namespace
}  // namespace houghloc
