#include "field_models/spl_import.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "field_models/field_validation.h"

namespace houghloc {
namespace {

using Json = nlohmann::json;

std::string dataPath(const std::string& name) {
  return std::string(HOUGHLOC_SOURCE_DIR) + "/tests/field_models/data/" + name;
}

Json splJson() {
  std::ifstream in(dataPath("spl2020_field_dimensions.json"));
  return Json::parse(in);
}

std::string importErrorOf(const std::string& text) {
  try {
    parseSplFieldDimensions(text, "dims.json");
  } catch (const FormatError& e) {
    return e.what();
  }
  return "(no error)";
}

void expectSameSegments(const FieldModel& a, const FieldModel& b) {
  ASSERT_EQ(a.segments.size(), b.segments.size());
  for (std::size_t i = 0; i < a.segments.size(); ++i) {
    EXPECT_EQ(a.segments[i].a, b.segments[i].a) << i;
    EXPECT_EQ(a.segments[i].b, b.segments[i].b) << i;
  }
  ASSERT_EQ(a.marks.size(), b.marks.size());
  for (std::size_t i = 0; i < a.marks.size(); ++i) EXPECT_EQ(a.marks[i].center, b.marks[i].center);
  ASSERT_EQ(a.arcs.size(), b.arcs.size());
  EXPECT_EQ(a.arcs[0].radius, b.arcs[0].radius);
}

TEST(SplImportTest, Spl2020FileGivesTheStandardField) {
  const FieldDimensions d = readSplFieldDimensions(dataPath("spl2020_field_dimensions.json"));
  const FieldDimensions s = standardFieldDimensions("spl");
  EXPECT_EQ(d.length, s.length);
  EXPECT_EQ(d.width, s.width);
  EXPECT_EQ(d.line_width, s.line_width);
  EXPECT_EQ(d.goal_area_length, 0.6);
  EXPECT_EQ(d.goal_area_width, 2.2);
  EXPECT_EQ(d.penalty_area_length, 1.65);
  EXPECT_EQ(d.penalty_area_width, 4.0);
  EXPECT_EQ(d.penalty_mark_distance, 1.3);
  EXPECT_EQ(d.penalty_mark_size, 0.1);
  EXPECT_EQ(d.center_circle_diameter, 1.5);
  EXPECT_EQ(d.border_strip_width, 0.7);
  EXPECT_EQ(d.goal_post_diameter, 0.1);
  EXPECT_EQ(d.goal_height, 0.8);
  EXPECT_EQ(d.goal_inner_width, 1.5);
  EXPECT_EQ(d.goal_depth, 0.5);
  EXPECT_EQ(d.corner_arc_radius, 0.0);
  expectSameSegments(importSplField(dataPath("spl2020_field_dimensions.json")),
                     makeStandardField("spl"));
}

TEST(SplImportTest, Spl2019FileHasNoGoalArea) {
  const FieldModel f = importSplField(dataPath("spl2019_field_dimensions.json"));
  EXPECT_EQ(f.segments.size(), 11u);
  expectSameSegments(f, makeStandardField("spl2019"));
  EXPECT_TRUE(validateField(f).empty());
}

TEST(SplImportTest, SmallerField) {
  const FieldModel f = importSplField(dataPath("small_field_dimensions.json"));
  EXPECT_EQ(f.field_length, 7.5);
  EXPECT_EQ(f.field_width, 5.0);  // written as the JSON integer 5
  EXPECT_EQ(f.segments.size(), 17u);
  EXPECT_EQ(f.arcs[0].radius, 0.625);
  bool mark = false;
  for (const Mark& m : f.marks) mark = mark || std::abs(m.center.x() - (3.75 - 1.1)) < 1e-12;
  EXPECT_TRUE(mark);
  EXPECT_EQ(f.goals[0].depth, 0.45);
  EXPECT_TRUE(validateField(f).empty());
  EXPECT_EQ(f.name, "SPL small_field_dimensions.json");
}

/// A change to the valid 2020 file and the text the error must contain.
struct Mutation {
  std::string label;
  std::function<void(Json&)> apply;
  std::string expected;
};

void PrintTo(const Mutation& m, std::ostream* os) { *os << m.label; }

class InvalidSplTest : public ::testing::TestWithParam<Mutation> {};

TEST_P(InvalidSplTest, RejectedNamingTheKey) {
  Json j = splJson();
  GetParam().apply(j);
  const std::string message = importErrorOf(j.dump(2));
  EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
  EXPECT_EQ(message.rfind("dims.json: ", 0), 0u) << message;
}

/// DESIGN §4's table, typed in again: key, min, max.
struct Range {
  const char* section;
  const char* key;
  double min, max;
};
const Range kRanges[] = {
    {"field", "length", 3, 20},
    {"field", "width", 3, 20},
    {"field", "lineWidth", 0.05, 0.05},
    {"field", "penaltyMarkSize", 0.01, 5},
    {"field", "goalAreaLength", 0.3, 10},
    {"field", "goalAreaWidth", 1, 10},
    {"field", "penaltyAreaWidth", 1, 10},
    {"field", "penaltyAreaLength", 0.3, 10},
    {"field", "penaltyMarkDistance", 0.3, 10},
    {"field", "centerCircleDiameter", 0.3, 10},
    {"field", "borderStripWidth", 0.2, 2},
    {"goal", "postDiameter", 0.01, 4},
    {"goal", "height", 0.3, 10},
    {"goal", "innerWidth", 0.3, 10},
    {"goal", "depth", 0.3, 10},
};

std::vector<Mutation> mutations() {
  std::vector<Mutation> m;
  auto set = [](const char* section, const char* key, Json value) {
    return [=](Json& j) { j[section][key] = value; };
  };
  for (const Range& r : kRanges) {
    const std::string name = std::string(r.section) + "." + r.key;
    const std::string label = std::string(r.section) + "_" + r.key;
    m.push_back({label + "_BelowRange", set(r.section, r.key, r.min - 0.001), name + ": "});
    m.push_back({label + "_AboveRange", set(r.section, r.key, r.max + 0.001), name + ": "});
    m.push_back({label + "_Zero", set(r.section, r.key, 0), name + ": must not be zero"});
    m.push_back({label + "_Negative", set(r.section, r.key, -r.max), name + ": "});
    m.push_back(
        {label + "_Bool", set(r.section, r.key, true), name + ": expected a number, got a bool"});
    m.push_back(
        {label + "_Null", set(r.section, r.key, nullptr), name + ": expected a number, got null"});
    m.push_back({label + "_String", set(r.section, r.key, "1.0"),
                 name + ": expected a number, got a string"});
    m.push_back(
        {label + "_Object", set(r.section, r.key, Json::object()), name + ": expected a number"});
    m.push_back({label + "_Array", set(r.section, r.key, Json::array({1.0})),
                 name + ": expected a number"});
    if (std::string(r.key) != "goalAreaLength" && std::string(r.key) != "goalAreaWidth") {
      m.push_back(
          {label + "_Missing", [=](Json& j) { j[r.section].erase(r.key); }, name + ": missing"});
    }
  }
  m.push_back({"OnlyGoalAreaLength", [](Json& j) { j["field"].erase("goalAreaWidth"); },
               "field.goalAreaWidth: missing"});
  m.push_back({"OnlyGoalAreaWidth", [](Json& j) { j["field"].erase("goalAreaLength"); },
               "field.goalAreaLength: missing"});
  m.push_back({"LineWidthNotExact", set("field", "lineWidth", 0.06),
               "field.lineWidth: must be exactly 0.05, got 0.06"});
  m.push_back(
      {"RangeMessage", set("field", "length", 25), "field.length: 25 is out of range [3, 20]"});
  m.push_back(
      {"UnknownFieldKey", set("field", "ballRadius", 0.05), "field.ballRadius: unknown key"});
  m.push_back(
      {"UnknownGoalKey", set("goal", "crossbarHeight", 0.8), "goal.crossbarHeight: unknown key"});
  m.push_back({"UnknownTopKey", [](Json& j) { j["ball"] = Json::object(); }, "ball: unknown key"});
  m.push_back({"MissingGoal", [](Json& j) { j.erase("goal"); }, "goal: missing"});
  m.push_back({"MissingField", [](Json& j) { j.erase("field"); }, "field: missing"});
  m.push_back({"FieldNotObject", [](Json& j) { j["field"] = 9.0; }, "field: expected an object"});
  m.push_back(
      {"GoalArray", [](Json& j) { j["goal"] = Json::array(); }, "goal: expected an object"});
  m.push_back({"TopLevelArray", [](Json& j) { j = Json::array({j}); }, "at the top level"});
  const std::pair<const char*, const char*> outdated[] = {
      {"penaltyMarkSize", "penaltyCrossSize"},
      {"penaltyMarkDistance", "penaltyCrossDistance"},
      {"goalAreaLength", "goalBoxAreaLength"},
      {"goalAreaWidth", "goalBoxAreaWidth"},
      {"penaltyMarkSize", "penaltyMarkerSize"}};
  for (const auto& [current, old] : outdated) {
    m.push_back({std::string("Outdated_") + old,
                 [current = current, old = old](Json& j) {
                   j["field"][old] = j["field"][current];
                   j["field"].erase(current);
                 },
                 std::string("field.") + old + ": outdated name, use field." + current});
  }
  return m;
}

INSTANTIATE_TEST_SUITE_P(Rules, InvalidSplTest, ::testing::ValuesIn(mutations()),
                         [](const auto& info) { return info.param.label; });

TEST(SplImportTest, RangeEndsAreAccepted) {
  for (const Range& r : kRanges) {
    for (double value : {r.min, r.max}) {
      Json j = splJson();
      j[r.section][r.key] = value;
      EXPECT_NO_THROW(parseSplFieldDimensions(j.dump(), "dims.json")) << r.key << " = " << value;
    }
  }
}

TEST(SplImportTest, TextLevelErrors) {
  std::string text = splJson().dump(2);
  // A key given twice; nlohmann alone would keep the last value silently.
  const std::string duplicated = text.replace(text.find("\"length\""), 0, "\"length\": 8.0,\n    ");
  EXPECT_NE(importErrorOf(duplicated).find("dims.json: field.length: duplicate key"),
            std::string::npos)
      << importErrorOf(duplicated);
  const std::string trailing_comma = "{\n  \"field\": {\"length\": 9.0,}\n}";
  EXPECT_NE(importErrorOf(trailing_comma).find("dims.json: invalid JSON at line 2"),
            std::string::npos)
      << importErrorOf(trailing_comma);
  EXPECT_NE(importErrorOf("").find("dims.json: invalid JSON"), std::string::npos);
  try {
    readSplFieldDimensions("/nonexistent/field_dimensions.json");
    FAIL();
  } catch (const FormatError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/field_dimensions.json: cannot open for reading");
  }
}

}  // namespace
}  // namespace houghloc
