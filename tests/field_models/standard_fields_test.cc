#include "field_models/standard_fields.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace houghloc {
namespace {

/// One row of the DESIGN §4 table, typed in independently of standard_fields.cc.
struct TableRow {
  const char* name;
  double length, width, line;
  double goal_area_length, goal_area_width;  // 0 = none
  double penalty_area_length, penalty_area_width;
  double mark_distance, mark_size;
  bool dot;
  double circle_diameter, border;
  double goal_inner, goal_post, goal_height;
  int corner_arcs;
};

void PrintTo(const TableRow& row, std::ostream* os) { *os << row.name; }

const TableRow kTable[] = {
    {"spl", 9, 6, 0.05, 0.6, 2.2, 1.65, 4.0, 1.3, 0.1, false, 1.5, 0.7, 1.5, 0.1, 0.8, 0},
    {"spl2019", 9, 6, 0.05, 0, 0, 0.6, 2.2, 1.3, 0.1, false, 1.5, 0.7, 1.5, 0.1, 0.8, 0},
    {"kid", 9, 6, 0.05, 1, 3, 2, 5, 1.5, 0.1, false, 1.5, 1.0, 2.6, 0.1, 1.2, 0},
    {"adult", 14, 9, 0.05, 1, 4, 3, 6, 2.1, 0.1, false, 3.0, 1.0, 2.6, 0.1, 1.8, 0},
    {"msl", 22, 14, 0.125, 0.75, 3.9, 2.25, 6.9, 3.6, 0.15, true, 4.0, 1.0, 2.0, 0.125, 1.0, 4},
};

constexpr double kFieldTol = 1e-12;

bool hasSegment(const FieldModel& f, double x1, double y1, double x2, double y2) {
  const Eigen::Vector2d a(x1, y1), b(x2, y2);
  for (const Segment2& s : f.segments) {
    if (((s.a - a).norm() < kFieldTol && (s.b - b).norm() < kFieldTol) ||
        ((s.a - b).norm() < kFieldTol && (s.b - a).norm() < kFieldTol)) {
      return true;
    }
  }
  return false;
}

class StandardFieldTest : public ::testing::TestWithParam<TableRow> {};

TEST_P(StandardFieldTest, DimensionsAndCounts) {
  const TableRow& t = GetParam();
  const FieldModel f = makeStandardField(t.name);
  EXPECT_EQ(f.field_length, t.length);
  EXPECT_EQ(f.field_width, t.width);
  EXPECT_EQ(f.line_width, t.line);
  EXPECT_EQ(f.border_strip_width, t.border);
  const bool goal_area = t.goal_area_length > 0.0;
  // 4 outer lines + halfway line + 3 lines per box and side.
  EXPECT_EQ(f.segments.size(), 5u + 2u * 3u * (goal_area ? 2u : 1u));
  EXPECT_EQ(f.arcs.size(), 1u + t.corner_arcs);
  EXPECT_EQ(f.marks.size(), 3u);
  EXPECT_EQ(f.goals.size(), 2u);
  double total = 0.0;
  for (const Segment2& s : f.segments) total += s.length();
  const double expected_total = 2 * t.length + 3 * t.width +
                                2 * (t.goal_area_width + 2 * t.goal_area_length) +
                                2 * (t.penalty_area_width + 2 * t.penalty_area_length);
  EXPECT_NEAR(total, expected_total, 1e-9);
}

TEST_P(StandardFieldTest, LinesWhereTheRulesDrawThem) {
  const TableRow& t = GetParam();
  const FieldModel f = makeStandardField(t.name);
  const double hl = t.length / 2, hw = t.width / 2;
  EXPECT_TRUE(hasSegment(f, -hl, hw, hl, hw)) << "left touch line";
  EXPECT_TRUE(hasSegment(f, -hl, -hw, hl, -hw)) << "right touch line";
  EXPECT_TRUE(hasSegment(f, -hl, -hw, -hl, hw)) << "own goal line";
  EXPECT_TRUE(hasSegment(f, hl, -hw, hl, hw)) << "opponent goal line";
  EXPECT_TRUE(hasSegment(f, 0, -hw, 0, hw)) << "halfway line";
  for (double side : {-1.0, 1.0}) {
    const double px = side * (hl - t.penalty_area_length), pw = t.penalty_area_width / 2;
    EXPECT_TRUE(hasSegment(f, px, -pw, px, pw)) << "penalty area front, side " << side;
    EXPECT_TRUE(hasSegment(f, side * hl, pw, px, pw)) << "penalty area left, side " << side;
    EXPECT_TRUE(hasSegment(f, side * hl, -pw, px, -pw)) << "penalty area right, side " << side;
    if (t.goal_area_length > 0.0) {
      const double gx = side * (hl - t.goal_area_length), gw = t.goal_area_width / 2;
      EXPECT_TRUE(hasSegment(f, gx, -gw, gx, gw)) << "goal area front, side " << side;
      EXPECT_TRUE(hasSegment(f, side * hl, gw, gx, gw)) << "goal area left, side " << side;
      EXPECT_TRUE(hasSegment(f, side * hl, -gw, gx, -gw)) << "goal area right, side " << side;
    }
  }
}

TEST_P(StandardFieldTest, CircleMarksGoalsAndCornerArcs) {
  const TableRow& t = GetParam();
  const FieldModel f = makeStandardField(t.name);
  const double hl = t.length / 2, hw = t.width / 2;
  ASSERT_FALSE(f.arcs.empty());
  EXPECT_EQ(f.arcs[0].center, Eigen::Vector2d::Zero());
  EXPECT_EQ(f.arcs[0].radius, t.circle_diameter / 2);
  EXPECT_TRUE(f.arcs[0].isFullCircle());

  const MarkShape shape = t.dot ? MarkShape::kDot : MarkShape::kCross;
  const double mark_x = hl - t.mark_distance;
  int centre = 0, own = 0, opponent = 0;
  for (const Mark& m : f.marks) {
    EXPECT_EQ(m.size, t.mark_size);  // the centre mark has the penalty mark's size
    EXPECT_EQ(m.shape, shape);
    EXPECT_NEAR(m.center.y(), 0.0, kFieldTol);
    centre += std::abs(m.center.x()) < kFieldTol;
    own += std::abs(m.center.x() + mark_x) < kFieldTol;
    opponent += std::abs(m.center.x() - mark_x) < kFieldTol;
  }
  EXPECT_EQ(centre, 1);
  EXPECT_EQ(own, 1);
  EXPECT_EQ(opponent, 1);

  for (const Goal& g : f.goals) {
    EXPECT_NEAR(std::abs(g.center.x()), hl, kFieldTol);
    EXPECT_NEAR(g.center.y(), 0.0, kFieldTol);
    EXPECT_EQ(g.inner_width, t.goal_inner);
    EXPECT_EQ(g.post_diameter, t.goal_post);
    EXPECT_EQ(g.height, t.goal_height);
  }
  EXPECT_NEAR(f.goals[0].center.x() + f.goals[1].center.x(), 0.0, kFieldTol);

  // Corner arcs: a quarter circle of radius 0.75 around each corner, lying inside the field.
  int corners = 0;
  for (std::size_t i = 1; i < f.arcs.size(); ++i) {
    const Arc2& a = f.arcs[i];
    EXPECT_NEAR(std::abs(a.center.x()), hl, kFieldTol);
    EXPECT_NEAR(std::abs(a.center.y()), hw, kFieldTol);
    EXPECT_EQ(a.radius, 0.75);
    EXPECT_NEAR(a.sweep_rad, M_PI / 2, kFieldTol);
    const Eigen::Vector2d middle = a.pointAt(a.start_rad + a.sweep_rad / 2);
    EXPECT_LT(std::abs(middle.x()), hl);
    EXPECT_LT(std::abs(middle.y()), hw);
    for (double end : {a.start_rad, a.start_rad + a.sweep_rad}) {  // ends on the two lines
      const Eigen::Vector2d p = a.pointAt(end);
      const bool on_goal_line = std::abs(std::abs(p.x()) - hl) < 1e-9;
      const bool on_touch_line = std::abs(std::abs(p.y()) - hw) < 1e-9;
      EXPECT_TRUE(on_goal_line != on_touch_line);
    }
    ++corners;
  }
  EXPECT_EQ(corners, t.corner_arcs);
}

INSTANTIATE_TEST_SUITE_P(AllFields, StandardFieldTest, ::testing::ValuesIn(kTable),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(StandardFieldsTest, SplPenaltyMarkAndNames) {
  const FieldModel spl = makeStandardField("spl");
  bool found = false;
  for (const Mark& m : spl.marks) found = found || std::abs(m.center.x() - (4.5 - 1.3)) < kFieldTol;
  EXPECT_TRUE(found) << "penalty mark at x = 4.5 - 1.3";
  EXPECT_EQ(standardFieldNames().size(), std::size(kTable));
  for (const TableRow& row : kTable) {
    EXPECT_NO_THROW(makeStandardField(row.name)) << row.name;
  }
  EXPECT_THROW(makeStandardField("spl2021"), std::invalid_argument);
}

}  // namespace
}  // namespace houghloc
