#include "field_models/field_validation.h"

#include <gtest/gtest.h>

#include <limits>

#include "field_models/standard_fields.h"

namespace houghloc {
namespace {

std::vector<std::string> issuesOf(const FieldModel& field) {
  std::vector<std::string> out;
  for (const FieldIssue& issue : validateField(field)) out.push_back(issue.toString());
  return out;
}

/// The SPL field with one change; `expected` must be the only issue (or a prefix of it).
void expectOnlyIssue(const FieldModel& field, const std::string& expected) {
  const std::vector<std::string> issues = issuesOf(field);
  ASSERT_EQ(issues.size(), 1u) << ::testing::PrintToString(issues);
  EXPECT_EQ(issues[0].rfind(expected, 0), 0u) << issues[0];
}

FieldModel spl() { return makeStandardField("spl"); }
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

TEST(FieldValidationTest, StandardFieldsAreValid) {
  for (const std::string& name : standardFieldNames()) {
    EXPECT_TRUE(validateField(makeStandardField(name)).empty())
        << name << ": " << ::testing::PrintToString(issuesOf(makeStandardField(name)));
  }
}

TEST(FieldValidationTest, Segments) {
  FieldModel f = spl();
  f.segments[2].b = f.segments[2].a;
  expectOnlyIssue(f, "segments[2]: zero length");

  f = spl();
  f.segments[4].b = f.segments[4].a + Eigen::Vector2d(0.0, 1e-4);
  expectOnlyIssue(f, "segments[4]: degenerate, length 0.0001 m");

  f = spl();
  f.segments.push_back(Segment2{f.segments[0].b, f.segments[0].a});  // reversed copy
  expectOnlyIssue(f, "segments[17]: duplicate of segments[0]");

  f = spl();
  f.segments.push_back(Segment2{{4.0, 3.0}, {5.0, 3.0}});  // on the touch line's end
  expectOnlyIssue(f, "segments[17]: overlaps segments[0] by 0.5 m");

  f = spl();  // collinear but only touching end to end: fine
  f.segments.push_back(Segment2{{4.5, 3.0}, {5.0, 3.0}});
  EXPECT_TRUE(validateField(f).empty());

  f = spl();
  f.segments[1].a.x() = kNan;
  expectOnlyIssue(f, "segments[1]: coordinate is not a finite number");

  f = spl();
  f.segments[0].b = Eigen::Vector2d(5.3, 3.0);  // carpet ends at 4.5 + 0.7 = 5.2
  expectOnlyIssue(f, "segments[0]: (5.3, 3) is outside the field plus border strip");
  f.segments[0].b = Eigen::Vector2d(5.2, 3.0);
  EXPECT_TRUE(validateField(f).empty());
}

TEST(FieldValidationTest, Arcs) {
  FieldModel f = spl();
  f.arcs[0].radius = 0.0;
  expectOnlyIssue(f, "arcs[0]: radius must be > 0, got 0");
  f = spl();
  f.arcs[0].start_rad = -M_PI;  // the interval is (-pi, pi]
  expectOnlyIssue(f, "arcs[0]: start must be in (-pi, pi]");
  f = spl();
  f.arcs[0].sweep_rad = 0.0;
  expectOnlyIssue(f, "arcs[0]: sweep must be in (0, 2pi], got 0");
  f = spl();
  f.arcs[0].sweep_rad = 7.0;
  expectOnlyIssue(f, "arcs[0]: sweep must be in (0, 2pi], got 7");
  f = spl();
  f.arcs[0].radius = std::numeric_limits<double>::infinity();
  expectOnlyIssue(f, "arcs[0]: value is not a finite number");
  f = spl();
  f.arcs[0].radius = 3.8;  // reaches y = 3.8 > 3.7
  expectOnlyIssue(f, "arcs[0]: (0, 3.8) is outside");
  // A quarter circle whose full circle would stick out but the arc itself does not.
  f = spl();
  f.arcs.push_back(Arc2{{4.5, 3.0}, 1.0, M_PI, 0.5 * M_PI});
  EXPECT_TRUE(validateField(f).empty()) << ::testing::PrintToString(issuesOf(f));
}

TEST(FieldValidationTest, MarksGoalsAndDimensions) {
  FieldModel f = spl();
  f.marks[1].size = -0.1;
  expectOnlyIssue(f, "marks[1]: size must be > 0");
  f = spl();
  f.marks[2].shape = static_cast<MarkShape>(3);
  expectOnlyIssue(f, "marks[2]: shape must be 0 (cross) or 1 (dot)");
  f = spl();
  f.marks[0].center.y() = -4.0;
  expectOnlyIssue(f, "marks[0]: (0, -4) is outside");
  f = spl();
  f.goals[1].depth = 0.0;
  expectOnlyIssue(f, "goals[1]: depth must be > 0, got 0");

  f = spl();
  f.line_width = 0.0;
  expectOnlyIssue(f, "line_width: must be > 0, got 0");
  f.line_width = kNan;
  expectOnlyIssue(f, "line_width: must be > 0, got nan");
  f = spl();
  f.border_strip_width = -0.1;
  // Without a known carpet nothing can be "outside"; only the dimension is reported.
  expectOnlyIssue(f, "border_strip_width: must be >= 0, got -0.1");
  f = spl();
  f.field_width = 5.0;  // touch lines now 0.5 m into the border: still inside 2.5 + 0.7
  EXPECT_TRUE(validateField(f).empty());
  f.field_width = 4.0;                    // touch lines at |y| = 3 > 2 + 0.7
  EXPECT_EQ(validateField(f).size(), 5u)  // both touch lines, both goal lines, halfway line
      << ::testing::PrintToString(issuesOf(f));

  FieldModel empty;
  expectOnlyIssue(empty, "map: no line features");
}

}  // namespace
}  // namespace houghloc
