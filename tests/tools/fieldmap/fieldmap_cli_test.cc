#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "field_models/field_yaml.h"
#include "field_models/standard_fields.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string dataPath(const std::string& name) {
  return std::string(HOUGHLOC_SOURCE_DIR) + "/tests/field_models/data/" + name;
}

class FieldmapCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(::testing::TempDir()) / (std::string("fieldmap_cli_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Runs houghloc-fieldmap with `args` (already shell-quoted where needed).
  RunResult run(const std::string& args) const {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command = std::string("'") + HOUGHLOC_FIELDMAP_EXE + "' " + args + " >'" +
                                out.string() + "' 2>'" + err.string() + "'";
    const int status = std::system(command.c_str());
    RunResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = slurp(out);
    result.err = slurp(err);
    return result;
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
  }

  fs::path dir_;
};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST_F(FieldmapCliTest, HelpForEverySubcommand) {
  RunResult r = run("--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* sub : {"new", "import-spl", "validate", "render"}) {
    EXPECT_TRUE(contains(r.out, sub)) << sub;
    const RunResult help = run(std::string(sub) + " --help");
    EXPECT_EQ(help.exit_code, 0) << sub;
    EXPECT_TRUE(contains(help.out, "Usage: houghloc-fieldmap " + std::string(sub))) << help.out;
    EXPECT_TRUE(contains(help.out, "Example:")) << help.out;
  }
  r = run("");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_TRUE(contains(r.err + r.out, "subcommand")) << r.err;
  EXPECT_NE(run("frobnicate").exit_code, 0);
}

TEST_F(FieldmapCliTest, NewWritesEveryStandardField) {
  for (const std::string& name : standardFieldNames()) {
    const RunResult r = run("new --standard " + name + " -o '" + path(name + ".yaml") + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "wrote " + path(name + ".yaml")));
    const FieldModel read = readFieldYaml(path(name + ".yaml"));
    const FieldModel expected = makeStandardField(name);
    EXPECT_EQ(read.name, expected.name);
    ASSERT_EQ(read.segments.size(), expected.segments.size());
    for (std::size_t i = 0; i < read.segments.size(); ++i) {
      EXPECT_EQ(read.segments[i].a, expected.segments[i].a);
      EXPECT_EQ(read.segments[i].b, expected.segments[i].b);
    }
    EXPECT_EQ(read.arcs.size(), expected.arcs.size());
    const RunResult v = run("validate '" + path(name + ".yaml") + "'");
    EXPECT_EQ(v.exit_code, 0) << v.err;
    EXPECT_TRUE(contains(v.out, "valid")) << v.out;
  }
}

TEST_F(FieldmapCliTest, NewRejectsBadArguments) {
  RunResult r = run("new --standard spl2030 -o '" + path("x.yaml") + "'");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_TRUE(contains(r.err, "--standard")) << r.err;
  EXPECT_TRUE(contains(r.err, "spl2030")) << r.err;
  EXPECT_FALSE(fs::exists(path("x.yaml")));

  r = run("new --standard spl");  // no -o
  EXPECT_NE(r.exit_code, 0);
  EXPECT_TRUE(contains(r.err, "--output")) << r.err;

  r = run("new --standard spl -o /nonexistent/dir/x.yaml");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(contains(r.err, "/nonexistent/dir/x.yaml: cannot open for writing")) << r.err;
}

TEST_F(FieldmapCliTest, ValidateReportsIssuesAndFormatErrors) {
  const std::string head =
      "%YAML:1.0\n---\nfield_length: 9\nfield_width: 6\nline_width: 0.05\n"
      "border_strip_width: 0.7\n";
  write("zero.yaml", head + "segments:\n  - [1, 1, 1, 1]\n  - [0, -3, 0, 3]\n  - [9, 0, 9, 1]\n");
  RunResult r = run("validate '" + path("zero.yaml") + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(contains(r.err, path("zero.yaml") + ": segments[0]: zero length")) << r.err;
  EXPECT_TRUE(contains(r.err, path("zero.yaml") + ": segments[2]: (9, 0) is outside")) << r.err;
  EXPECT_TRUE(contains(r.err, "2 issue(s)")) << r.err;

  write("short.yaml", head + "segments:\n  - [0, -3, 0, 3]\n  - [1, 2, 3]\n");
  r = run("validate '" + path("short.yaml") + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(contains(r.err, path("short.yaml") + ": segments[1]: expected 4 numbers, got 3"))
      << r.err;

  write("key.yaml", head + "segments: []\nlinewidth: 0.05\n");
  r = run("validate '" + path("key.yaml") + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(contains(r.err, path("key.yaml") + ": linewidth: unknown key")) << r.err;

  r = run("validate '" + path("missing.yaml") + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(contains(r.err, path("missing.yaml") + ": cannot open for reading")) << r.err;

  EXPECT_NE(run("validate").exit_code, 0);  // FILE is required
}

TEST_F(FieldmapCliTest, ImportSplValidFiles) {
  struct Case {
    const char* file;
    const char* standard;  // nullptr: no standard field to compare with
    std::size_t segments;
  };
  for (const Case& c : {Case{"spl2020_field_dimensions.json", "spl", 17},
                        Case{"spl2019_field_dimensions.json", "spl2019", 11},
                        Case{"small_field_dimensions.json", nullptr, 17}}) {
    const std::string out = path(std::string(c.file) + ".yaml");
    const RunResult r = run("import-spl '" + dataPath(c.file) + "' -o '" + out + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const FieldModel f = readFieldYaml(out);
    ASSERT_EQ(f.segments.size(), c.segments);
    if (c.standard) {
      const FieldModel expected = makeStandardField(c.standard);
      for (std::size_t i = 0; i < f.segments.size(); ++i) {
        EXPECT_EQ(f.segments[i].a, expected.segments[i].a) << c.file << " " << i;
        EXPECT_EQ(f.segments[i].b, expected.segments[i].b) << c.file << " " << i;
      }
    } else {
      EXPECT_EQ(f.field_length, 7.5);
    }
    EXPECT_EQ(run("validate '" + out + "'").exit_code, 0);
  }
}

TEST_F(FieldmapCliTest, ImportSplRejectsInvalidFiles) {
  std::string json = slurp(dataPath("spl2020_field_dimensions.json"));
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string copy = json;
    copy.replace(copy.find(from), from.size(), to);
    return copy;
  };
  struct Case {
    std::string name, text, expected;
  };
  const Case cases[] = {
      {"line.json", replaced("\"lineWidth\": 0.05", "\"lineWidth\": 0.04"), "field.lineWidth"},
      {"old.json", replaced("penaltyMarkSize", "penaltyCrossSize"), "field.penaltyCrossSize"},
      {"bool.json", replaced("\"depth\": 0.5", "\"depth\": true"), "goal.depth"},
      {"half.json", replaced("\"goalAreaWidth\": 2.2,", ""), "field.goalAreaWidth"},
      {"syntax.json", replaced("\"width\": 6.0,", "\"width\": 6.0,,"), "invalid JSON at line 4"},
      // Every value in range, but the penalty area is wider than the carpet: no map.
      {"wide.json", replaced("\"penaltyAreaWidth\": 4.0", "\"penaltyAreaWidth\": 9.0"),
       "penaltyAreaWidth"},
  };
  for (const Case& c : cases) {
    write(c.name, c.text);
    const RunResult r =
        run("import-spl '" + path(c.name) + "' -o '" + path(c.name + ".yaml") + "'");
    EXPECT_EQ(r.exit_code, 1) << c.name;
    EXPECT_TRUE(contains(r.err, path(c.name))) << r.err;
    if (c.name != "wide.json") {
      EXPECT_TRUE(contains(r.err, c.expected)) << r.err;
    } else {
      EXPECT_TRUE(contains(r.err, "is outside the field plus border strip")) << r.err;
      EXPECT_TRUE(contains(r.err, "not written")) << r.err;
    }
    EXPECT_FALSE(fs::exists(path(c.name + ".yaml"))) << c.name;
  }
  const RunResult r = run("import-spl '" + path("none.json") + "' -o '" + path("none.yaml") + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(contains(r.err, path("none.json") + ": cannot open for reading")) << r.err;
}

/// Pixel containing field point (x, y) for the layout the docs describe: carpet (field plus
/// border) centred, x to the right, y up, `margin` pixels around it.
cv::Vec3b pixelAt(const cv::Mat& image, const FieldModel& f, double scale, int margin, double x,
                  double y) {
  const int u = static_cast<int>(std::floor(margin + (x + f.outerHalfLength()) * scale));
  const int v = static_cast<int>(std::floor(margin + (f.outerHalfWidth() - y) * scale));
  return image.at<cv::Vec3b>(v, u);
}

bool isWhite(const cv::Vec3b& p) { return p[0] >= 250 && p[1] >= 250 && p[2] >= 250; }

TEST_F(FieldmapCliTest, RenderDrawsLinesWhereTheMapHasThem) {
  ASSERT_EQ(run("new --standard spl -o '" + path("spl.yaml") + "'").exit_code, 0);
  const RunResult r = run("render '" + path("spl.yaml") + "' -o '" + path("spl.png") + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const cv::Mat image = cv::imread(path("spl.png"), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  // Default 100 px/m and 40 px margin: (9 + 2 * 0.7) m x (6 + 2 * 0.7) m of carpet.
  EXPECT_EQ(image.cols, 1040 + 80);
  EXPECT_EQ(image.rows, 740 + 80);
  const FieldModel f = makeStandardField("spl");
  const std::pair<double, double> on_lines[] = {
      {-2.0, 3.0},
      {2.0, -3.0},
      {-4.5, -2.5},
      {4.5, 2.5},  // touch and goal lines
      {0.0, -2.0},
      {2.85, 1.0},
      {-2.85, -1.5},  // halfway, penalty area fronts
      {3.9, 0.5},
      {4.2, 1.1},
      {-3.2, 0.0},                                    // goal area, penalty mark
      {0.75 * std::cos(0.5), 0.75 * std::sin(0.5)}};  // centre circle
  for (const auto& [x, y] : on_lines) {
    EXPECT_TRUE(isWhite(pixelAt(image, f, 100, 40, x, y)))
        << x << ", " << y << ": " << pixelAt(image, f, 100, 40, x, y);
  }
  // Carpet between lines is green, the frame around it is not carpet.
  const cv::Vec3b grass = pixelAt(image, f, 100, 40, 1.5, 1.5);
  EXPECT_GT(grass[1], grass[0] + 50);
  EXPECT_GT(grass[1], grass[2] + 50);
  EXPECT_FALSE(isWhite(pixelAt(image, f, 100, 40, 2.85 + 0.1, 1.0)));  // 2 line widths off
  EXPECT_FALSE(isWhite(pixelAt(image, f, 100, 40, 1.5, 3.0 - 0.06)));
  // The field is symmetric, so the lines cannot tell a flipped view; the axes can: the red x
  // arrow points right (toward the opponent goal), the blue y arrow up, both 1 m long.
  for (double along : {0.3, 0.8}) {
    const cv::Vec3b x_arrow = pixelAt(image, f, 100, 40, along, 0.0);  // BGR
    EXPECT_GT(x_arrow[2], 150);
    EXPECT_LT(x_arrow[1], 100);
    const cv::Vec3b y_arrow = pixelAt(image, f, 100, 40, 0.0, along);
    EXPECT_GT(y_arrow[0], 150);
    EXPECT_LT(y_arrow[2], 100);
    EXPECT_TRUE(isWhite(pixelAt(image, f, 100, 40, -along, 0.0)) ||
                pixelAt(image, f, 100, 40, -along, 0.0)[1] > 100);  // no arrow to the left
    EXPECT_LT(pixelAt(image, f, 100, 40, -along, 0.0)[2], 150);
    EXPECT_TRUE(isWhite(pixelAt(image, f, 100, 40, 0.0, -along)));  // halfway line, no arrow
  }
  const cv::Vec3b frame = image.at<cv::Vec3b>(5, 5);
  EXPECT_EQ(frame[0], frame[1]);
  EXPECT_EQ(frame[1], frame[2]);
}

TEST_F(FieldmapCliTest, RenderScaleAndErrors) {
  ASSERT_EQ(run("new --standard msl -o '" + path("msl.yaml") + "'").exit_code, 0);
  RunResult r = run("render '" + path("msl.yaml") + "' -o '" + path("msl.png") + "' --scale 20");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const cv::Mat image = cv::imread(path("msl.png"), cv::IMREAD_COLOR);
  EXPECT_EQ(image.cols, 24 * 20 + 80);
  EXPECT_EQ(image.rows, 16 * 20 + 80);
  // The MSL touch line is 0.125 m = 2.5 px wide at this scale; its centre pixel is white.
  EXPECT_TRUE(isWhite(pixelAt(image, makeStandardField("msl"), 20, 40, 3.0, -7.0)));

  r = run("render '" + path("msl.yaml") + "' -o '" + path("msl.png") + "' --scale 0");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_TRUE(contains(r.err, "--scale")) << r.err;

  r = run("render '" + path("msl.yaml") + "' -o /nonexistent/dir/msl.png");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(contains(r.err, "/nonexistent/dir/msl.png: cannot write image")) << r.err;

  r = run("render '" + path("msl.yaml") + "' -o '" + path("msl.unknown") + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(contains(r.err, path("msl.unknown") + ": cannot write image")) << r.err;

  write("bad.yaml", "%YAML:1.0\n---\nfield_length: 9\n");
  r = run("render '" + path("bad.yaml") + "' -o '" + path("bad.png") + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(contains(r.err, path("bad.yaml") + ": field_width: missing")) << r.err;
  EXPECT_FALSE(fs::exists(path("bad.png")));
}

}  // namespace
}  // namespace houghloc
