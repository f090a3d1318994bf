#include "field_models/field_yaml.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "field_models/standard_fields.h"

namespace houghloc {
namespace {

/// Exact equality of every number: the round trip must not lose a bit.
void expectSameField(const FieldModel& a, const FieldModel& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.field_length, b.field_length);
  EXPECT_EQ(a.field_width, b.field_width);
  EXPECT_EQ(a.line_width, b.line_width);
  EXPECT_EQ(a.border_strip_width, b.border_strip_width);
  ASSERT_EQ(a.segments.size(), b.segments.size());
  for (std::size_t i = 0; i < a.segments.size(); ++i) {
    EXPECT_EQ(a.segments[i].a, b.segments[i].a) << "segments[" << i << "]";
    EXPECT_EQ(a.segments[i].b, b.segments[i].b) << "segments[" << i << "]";
  }
  ASSERT_EQ(a.arcs.size(), b.arcs.size());
  for (std::size_t i = 0; i < a.arcs.size(); ++i) {
    EXPECT_EQ(a.arcs[i].center, b.arcs[i].center);
    EXPECT_EQ(a.arcs[i].radius, b.arcs[i].radius);
    EXPECT_EQ(a.arcs[i].start_rad, b.arcs[i].start_rad);
    EXPECT_EQ(a.arcs[i].sweep_rad, b.arcs[i].sweep_rad);
  }
  ASSERT_EQ(a.marks.size(), b.marks.size());
  for (std::size_t i = 0; i < a.marks.size(); ++i) {
    EXPECT_EQ(a.marks[i].center, b.marks[i].center);
    EXPECT_EQ(a.marks[i].size, b.marks[i].size);
    EXPECT_EQ(a.marks[i].shape, b.marks[i].shape);
  }
  ASSERT_EQ(a.goals.size(), b.goals.size());
  for (std::size_t i = 0; i < a.goals.size(); ++i) {
    EXPECT_EQ(a.goals[i].center, b.goals[i].center);
    EXPECT_EQ(a.goals[i].inner_width, b.goals[i].inner_width);
    EXPECT_EQ(a.goals[i].post_diameter, b.goals[i].post_diameter);
    EXPECT_EQ(a.goals[i].height, b.goals[i].height);
    EXPECT_EQ(a.goals[i].depth, b.goals[i].depth);
  }
}

std::string yamlErrorOf(const std::string& yaml) {
  try {
    parseFieldYaml(yaml, "field.yaml");
  } catch (const FormatError& e) {
    return e.what();
  }
  return "(no error)";
}

class StandardFieldYamlTest : public ::testing::TestWithParam<std::string> {};

TEST_P(StandardFieldYamlTest, RoundTripIsExact) {
  const FieldModel field = makeStandardField(GetParam());
  expectSameField(parseFieldYaml(fieldToYaml(field), "memory"), field);

  const std::string path = ::testing::TempDir() + "/houghloc_" + GetParam() + ".yaml";
  writeFieldYaml(field, path);
  expectSameField(readFieldYaml(path), field);
  std::remove(path.c_str());
}

INSTANTIATE_TEST_SUITE_P(AllFields, StandardFieldYamlTest,
                         ::testing::ValuesIn(standardFieldNames()));

TEST(FieldYamlTest, RoundTripKeepsAwkwardValues) {
  FieldModel field;
  field.name = "lab 2: hall B #3";
  field.line_width = 0.1 + 0.2;  // not 0.3
  field.segments = {Segment2{{1.0 / 3.0, -1e-300}, {-0.0, 4.999999999999999}}};
  field.arcs = {Arc2{{M_E, -M_PI}, 0.1, -M_PI + 1e-15, 2.0 * M_PI}};
  field.marks = {Mark{{2.0 / 7.0, 1e10}, 5e-324, MarkShape::kDot}};
  field.goals = {};
  const FieldModel back = parseFieldYaml(fieldToYaml(field), "memory");
  expectSameField(back, field);
  EXPECT_TRUE(back.goals.empty());
}

TEST(FieldYamlTest, NumericNameStaysAString) {
  FieldModel field = makeStandardField("spl");
  field.name = "2024";
  EXPECT_EQ(parseFieldYaml(fieldToYaml(field), "memory").name, "2024");
  field.name = "say \"hi\"";
  EXPECT_THROW(fieldToYaml(field), FormatError);
}

TEST(FieldYamlTest, ReadsTheDesignExampleWithoutHeader) {
  const std::string yaml =
      "name: \"SPL 2020\"\n"
      "field_length: 9.0          # between goal lines, m\n"
      "field_width: 6.0\n"
      "line_width: 0.05\n"
      "border_strip_width: 0.7\n"
      "segments:                  # x1, y1, x2, y2\n"
      "   - [ -4.5, -3.0, 4.5, -3.0 ]\n"
      "arcs:\n"
      "   - [ 0.0, 0.0, 0.75, 0.0, 6.283185307179586 ]\n"
      "marks:\n"
      "   - [ 3.2, 0.0, 0.1, 0 ]\n"
      "goals:\n"
      "   - [ 4.5, 0.0, 1.5, 0.1, 0.8, 0.5 ]\n";
  const FieldModel f = parseFieldYaml(yaml, "example.yaml");
  EXPECT_EQ(f.name, "SPL 2020");
  EXPECT_EQ(f.field_length, 9.0);
  EXPECT_EQ(f.line_width, 0.05);
  ASSERT_EQ(f.segments.size(), 1u);
  EXPECT_EQ(f.segments[0].a, Eigen::Vector2d(-4.5, -3.0));
  EXPECT_EQ(f.segments[0].b, Eigen::Vector2d(4.5, -3.0));
  ASSERT_EQ(f.arcs.size(), 1u);
  EXPECT_EQ(f.arcs[0].sweep_rad, 2.0 * M_PI);
  ASSERT_EQ(f.marks.size(), 1u);
  EXPECT_EQ(f.marks[0].center.x(), 3.2);
  EXPECT_EQ(f.marks[0].shape, MarkShape::kCross);
  ASSERT_EQ(f.goals.size(), 1u);
  EXPECT_EQ(f.goals[0].depth, 0.5);
}

const std::string kHead =
    "%YAML:1.0\n---\nfield_length: 9\nfield_width: 6\nline_width: 0.05\n"
    "border_strip_width: 0.7\n";

struct BadYaml {
  const char* label;
  std::string text;
  const char* expected;  ///< substring of the error message
};

void PrintTo(const BadYaml& c, std::ostream* os) { *os << c.label; }

class BadYamlTest : public ::testing::TestWithParam<BadYaml> {};

TEST_P(BadYamlTest, ErrorNamesFileAndEntry) {
  const std::string message = yamlErrorOf(GetParam().text);
  EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
  EXPECT_EQ(message.rfind("field.yaml: ", 0), 0u) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadYamlTest,
    ::testing::Values(
        BadYaml{"ShortSegment", kHead + "segments:\n  - [0, 0, 1, 0]\n  - [1, 2, 3]\n",
                "field.yaml: segments[1]: expected 4 numbers, got 3"},
        BadYaml{"TextInArc", kHead + "segments: []\narcs:\n  - [0, 0, r, 0, 1]\n",
                "field.yaml: arcs[0]: expected 5 numbers; item 2 is not"},
        BadYaml{"ScalarEntry", kHead + "segments:\n  - 4\n", "segments[0]: expected 4 numbers"},
        BadYaml{"BadShape", kHead + "segments: []\nmarks:\n  - [0, 0, 0.1, 2]\n",
                "marks[0]: shape must be 0 (cross) or 1 (dot)"},
        BadYaml{"ShortGoal", kHead + "segments: []\ngoals:\n  - [4.5, 0, 1.5, 0.1, 0.8]\n",
                "goals[0]: expected 6 numbers, got 5"},
        BadYaml{"MissingLineWidth",
                "%YAML:1.0\n---\nfield_length: 9\nfield_width: 6\nborder_strip_width: 0.7\n"
                "segments: []\n",
                "field.yaml: line_width: missing"},
        BadYaml{"MissingSegments", kHead, "field.yaml: segments: missing"},
        BadYaml{"TextWidth",
                "%YAML:1.0\n---\nfield_length: 9\nfield_width: wide\nline_width: 0.05\n"
                "border_strip_width: 0.7\nsegments: []\n",
                "field.yaml: field_width: expected a number"},
        BadYaml{"DuplicateKey", kHead + "segments: []\nfield_width: 7\n",
                "field.yaml: field_width: duplicate key"},
        BadYaml{"UnknownKey", kHead + "segment: []\n", "field.yaml: segment: unknown key"},
        BadYaml{"SegmentsNotList", kHead + "segments: 3\n", "segments: expected a list"},
        BadYaml{"NameNotString", kHead + "segments: []\nname: [1]\n", "name: expected a string"},
        BadYaml{"Syntax", kHead + "segments: [ [0, 0, 1, 0]\n", "field.yaml: line "},
        BadYaml{"TopLevelList", "%YAML:1.0\n---\n- 1\n- 2\n", "top level"},
        BadYaml{"Empty", "  \n", "field.yaml: empty file"}),
    [](const auto& info) { return std::string(info.param.label); });

TEST(FieldYamlTest, SyntaxErrorLineCountsTheUsersLines) {
  // Without a header the reader prepends one; the reported line must still be the user's.
  const std::string message = yamlErrorOf("field_length: 9\nfield_width: 6\n  line_width: 0.05\n");
  EXPECT_NE(message.find("field.yaml: line 3:"), std::string::npos) << message;
}

TEST(FieldYamlTest, FileErrorsNameThePath) {
  try {
    readFieldYaml("/nonexistent/dir/field.yaml");
    FAIL() << "no error";
  } catch (const FormatError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/dir/field.yaml: cannot open for reading");
  }
  try {
    writeFieldYaml(makeStandardField("spl"), "/nonexistent/dir/out.yaml");
    FAIL() << "no error";
  } catch (const FormatError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/dir/out.yaml: cannot open for writing");
  }
}

}  // namespace
}  // namespace houghloc
