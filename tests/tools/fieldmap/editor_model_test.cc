// The field-map editor's model without a display: edits and undo, snapping, symmetry,
// regeneration, validation, YAML and field_dimensions.json round trips.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <string>

#include "field_models/field_yaml.h"
#include "field_models/format_error.h"
#include "field_models/spl_import.h"
#include "tools/fieldmap/editor_model/document_io.h"
#include "tools/fieldmap/editor_model/document_validation.h"
#include "tools/fieldmap/editor_model/edit_commands.h"
#include "tools/fieldmap/editor_model/snapping.h"
#include "tools/fieldmap/editor_model/symmetry.h"

namespace houghloc::fieldmap {
namespace {

using Eigen::Vector2d;

std::string tempPath(const std::string& name) {
  return std::string(::testing::TempDir()) + "/editor_model_" + name;
}

FieldDimensions smallField() {  // the lab field of the docs: 7.5 x 5 m, 0.5 m goal area
  FieldDimensions d;
  d.name = "lab";
  d.length = 7.5;
  d.width = 5.0;
  d.goal_area_length = 0.5;
  d.goal_area_width = 1.8;
  d.penalty_area_length = 1.2;
  d.penalty_area_width = 3.2;
  d.penalty_mark_distance = 1.1;
  d.center_circle_diameter = 1.2;
  d.border_strip_width = 0.5;
  return d;
}

TEST(EditorDocument, IdsAreStableWhenOtherFeaturesGo) {
  EditorDocument doc = standardDocument("spl");
  const FeatureId halfway = doc.idAt(EditorKind::kSegment, 4);
  const Segment2 line = doc.segment(halfway);
  doc.remove(doc.idAt(EditorKind::kSegment, 0));
  EXPECT_EQ(doc.indexOf(halfway), 3);
  EXPECT_TRUE(doc.segment(halfway).a.isApprox(line.a));
  EXPECT_THROW(doc.remove({EditorKind::kSegment, 999}), std::out_of_range);
}

TEST(EditCommands, EveryEditAndItsUndo) {
  EditorDocument doc = standardDocument("spl");
  const EditorDocument original = doc;
  const FeatureId seg = doc.idAt(EditorKind::kSegment, 4);
  const FeatureId circle = doc.idAt(EditorKind::kArc, 0);
  const FeatureId mark = doc.idAt(EditorKind::kMark, 1);
  const FeatureId goal = doc.idAt(EditorKind::kGoal, 1);
  EditHistory history;

  history.push(moveHandle(doc, seg, Handle::kEnd, Vector2d(0.5, 3.0)), doc);
  EXPECT_EQ(doc.segment(seg).b, Vector2d(0.5, 3.0));
  history.push(moveHandle(doc, circle, Handle::kRadius, Vector2d(0.0, -1.0)), doc);
  EXPECT_DOUBLE_EQ(doc.arc(circle).radius, 1.0);
  history.push(setArc(doc, circle, Arc2{Vector2d(1, 1), 0.5, 3 * M_PI / 2, M_PI / 2}), doc);
  EXPECT_NEAR(doc.arc(circle).start_rad, -M_PI / 2, 1e-12);  // normalized into (-pi, pi]
  history.push(moveHandle(doc, circle, Handle::kArcEnd, Vector2d(1.0, 2.0)), doc);
  EXPECT_NEAR(doc.arc(circle).sweep_rad, M_PI, 1e-12);  // end moved from 0 to pi/2
  history.push(moveHandle(doc, circle, Handle::kArcStart, Vector2d(2.0, 1.0)), doc);
  EXPECT_NEAR(doc.arc(circle).start_rad, 0.0, 1e-12);
  EXPECT_NEAR(doc.arc(circle).sweep_rad, M_PI / 2, 1e-12);
  history.push(setMark(doc, mark, Mark{Vector2d(-3, 0.5), 0.2, MarkShape::kDot}), doc);
  history.push(setGoal(doc, goal, Goal{Vector2d(4.4, 0), 1.2, 0.1, 0.8, 0.4}), doc);
  history.push(translateFeatures(doc, {seg, mark, goal}, Vector2d(0.1, -0.2)), doc);
  EXPECT_TRUE(doc.mark(mark).center.isApprox(Vector2d(-2.9, 0.3)));
  EXPECT_TRUE(doc.goal(goal).center.isApprox(Vector2d(4.5, -0.2)));
  history.push(addSegment(doc, Segment2{Vector2d(1, 1), Vector2d(2, 1)}), doc);
  history.push(addArc(doc, Arc2{Vector2d(0, 0), 2.0, 0.0, 1.0}), doc);
  history.push(addMark(doc, Mark{}), doc);
  history.push(addGoal(doc, Goal{}), doc);
  EXPECT_EQ(doc.field().segments.size(), original.field().segments.size() + 1);
  history.push(deleteFeatures(doc, {seg, circle}), doc);
  EXPECT_FALSE(doc.contains(seg));
  FieldModel header = doc.field();
  header.field_length = 8.0;
  history.push(setHeader(doc, header), doc);
  EXPECT_DOUBLE_EQ(doc.field().field_length, 8.0);
  history.push(regenerate(doc, smallField()), doc);
  EXPECT_TRUE(doc.isRulesShaped());
  const EditorDocument last = doc;

  int undone = 0;
  while (history.undo(doc)) ++undone;
  EXPECT_EQ(undone, 15);
  EXPECT_TRUE(sameField(doc.field(), original.field(), 0.0));
  EXPECT_EQ(doc.ids(EditorKind::kSegment), original.ids(EditorKind::kSegment));
  while (history.redo(doc)) {
  }
  EXPECT_TRUE(sameField(doc.field(), last.field(), 0.0));
  EXPECT_FALSE(history.canRedo());
}

TEST(EditCommands, FreeEditEndsRulesShape) {
  EditorDocument doc = standardDocument("spl");
  EXPECT_TRUE(doc.isRulesShaped());
  EditHistory history;
  history.push(
      moveHandle(doc, doc.idAt(EditorKind::kSegment, 4), Handle::kStart, Vector2d(0.1, -3.0)), doc);
  EXPECT_FALSE(doc.isRulesShaped());
  history.undo(doc);
  EXPECT_TRUE(doc.isRulesShaped());
}

TEST(Snapping, EndpointParallelPerpendicularGrid) {
  const EditorDocument doc = standardDocument("spl");  // corners at (+-4.5, +-3)
  const SnapConfig config;                             // 5 cm grid, 10 cm endpoint radius
  SnapResult r = snapPoint(doc, Vector2d(4.43, 2.95), std::nullopt, std::nullopt, config);
  EXPECT_EQ(r.kind, SnapKind::kEndpoint);
  EXPECT_EQ(r.point, Vector2d(4.5, 3.0));

  // From (1, 1), a point 2 m away 0.02 rad off the x axis turns parallel to the touch lines.
  const Vector2d anchor(1.0, 1.0);
  r = snapPoint(doc, anchor + 2.0 * Vector2d(std::cos(0.02), std::sin(0.02)), std::nullopt, anchor,
                config);
  EXPECT_TRUE(r.kind == SnapKind::kParallel || r.kind == SnapKind::kPerpendicular);
  EXPECT_NEAR(r.point.x(), 3.0, 1e-12);
  EXPECT_NEAR(r.point.y(), 1.0, 1e-12);

  // A tilted segment: a direction near its normal snaps perpendicular to it.
  EditorDocument tilted(FieldModel{});
  tilted.header().segments.clear();
  const FeatureId diag = tilted.add(Segment2{Vector2d(-1, -1), Vector2d(1, 1)});
  const Vector2d n = Vector2d(-1, 1).normalized();
  const Vector2d off = Eigen::Rotation2Dd(0.03) * n;
  r = snapPoint(tilted, Vector2d(3, 0) + 1.5 * off, std::nullopt, Vector2d(3, 0), config);
  EXPECT_EQ(r.kind, SnapKind::kPerpendicular);
  EXPECT_EQ(r.target, diag);
  EXPECT_TRUE(r.point.isApprox(Vector2d(3, 0) + 1.5 * n));

  r = snapPoint(doc, Vector2d(1.234, -0.876), std::nullopt, std::nullopt, config);
  EXPECT_EQ(r.kind, SnapKind::kGrid);
  EXPECT_TRUE(r.point.isApprox(Vector2d(1.25, -0.9)));
  SnapConfig off_config;
  off_config.enabled = false;
  EXPECT_EQ(snapPoint(doc, Vector2d(4.43, 2.95), std::nullopt, std::nullopt, off_config).point,
            Vector2d(4.43, 2.95));
}

TEST(Symmetry, MirroredCornerArcsAreTheRulesCornerArcs) {
  // MSL's makeField draws the four corner arcs independently: mirrors of the first must match.
  const FieldModel msl = makeStandardField("msl");
  const Arc2& first = msl.arcs[1];  // around (hl, hw)
  const Arc2 expected[] = {msl.arcs[4], msl.arcs[2], msl.arcs[3]};
  const Mirror mirrors[] = {Mirror::kAcrossXAxis, Mirror::kAcrossYAxis, Mirror::kThroughCenter};
  for (int i = 0; i < 3; ++i) {
    const Arc2 m = mirrored(first, mirrors[i]);
    EXPECT_TRUE(m.center.isApprox(expected[i].center)) << i;
    EXPECT_NEAR(m.start_rad, expected[i].start_rad, 1e-12) << i;
    EXPECT_NEAR(m.sweep_rad, expected[i].sweep_rad, 1e-12) << i;
  }
}

TEST(Symmetry, MirroringOneHalfRebuildsTheField) {
  // Delete the opponent half's goal and penalty boxes (segments 11-16) and penalty mark, then
  // mirror the own half's (segments 5-10) across the y axis.
  EditorDocument doc = standardDocument("spl");
  const FieldModel full = doc.field();
  std::vector<FeatureId> own, opponent;
  for (int i = 5; i < 17; ++i)
    (i < 11 ? own : opponent).push_back(doc.idAt(EditorKind::kSegment, i));
  own.push_back(doc.idAt(EditorKind::kMark, 1));
  opponent.push_back(doc.idAt(EditorKind::kMark, 2));
  doc = deleteFeatures(doc, opponent).after;
  doc = mirrorFeatures(doc, own, Mirror::kAcrossYAxis).after;
  ASSERT_EQ(doc.field().segments.size(), full.segments.size());
  for (int k = 0; k < 6; ++k) {
    const Segment2& got = doc.field().segments[full.segments.size() - 6 + k];
    const Segment2& want = full.segments[11 + k];
    EXPECT_TRUE(got.a.isApprox(want.a) && got.b.isApprox(want.b)) << k;
  }
  EXPECT_TRUE(doc.field().marks.back().center.isApprox(full.marks[2].center));
}

TEST(Regeneration, SmallFieldFromDimensions) {
  const EditorDocument doc = regenerate(standardDocument("spl"), smallField()).after;
  const FieldModel& f = doc.field();
  EXPECT_DOUBLE_EQ(f.field_length, 7.5);
  EXPECT_DOUBLE_EQ(f.field_width, 5.0);
  // Goal-area front line at x = -(3.75 - 0.5), from y = -0.9 to 0.9.
  EXPECT_TRUE(f.segments[5].a.isApprox(Vector2d(-3.25, -0.9)));
  EXPECT_TRUE(f.segments[5].b.isApprox(Vector2d(-3.25, 0.9)));
  EXPECT_TRUE(f.marks[2].center.isApprox(Vector2d(3.75 - 1.1, 0.0)));
  EXPECT_DOUBLE_EQ(f.arcs[0].radius, 0.6);
  EXPECT_TRUE(validateDocument(doc).empty());
}

TEST(Validation, MessagesNameTheFeature) {
  EditorDocument doc = standardDocument("spl");
  const FeatureId seg = doc.idAt(EditorKind::kSegment, 4);
  doc = moveHandle(doc, seg, Handle::kEnd, doc.segment(seg).a).after;  // zero length
  doc = moveHandle(doc, doc.idAt(EditorKind::kMark, 0), Handle::kCenter, Vector2d(9, 0)).after;
  FieldModel header = doc.field();
  header.line_width = 0.0;
  doc = setHeader(doc, header).after;
  const std::vector<DocumentIssue> issues = validateDocument(doc);
  ASSERT_EQ(issues.size(), 3u);
  bool segment_seen = false, mark_seen = false, width_seen = false;
  for (const DocumentIssue& issue : issues) {
    if (issue.feature == std::optional<FeatureId>(seg)) segment_seen = true;
    if (issue.feature == std::optional<FeatureId>(doc.idAt(EditorKind::kMark, 0)))
      mark_seen = issue.text.find("outside") != std::string::npos;
    if (!issue.feature) width_seen = issue.text.rfind("line_width", 0) == 0;
  }
  EXPECT_TRUE(segment_seen && mark_seen && width_seen);
}

TEST(DocumentIo, YamlRoundTripIsExact) {
  EditorDocument doc = regenerate(standardDocument("spl"), smallField()).after;
  doc = addArc(doc, Arc2{Vector2d(0.1, 0.2), 1.0 / 3.0, 0.7, 2.1}).after;
  const std::string path = tempPath("round.yaml");
  saveDocument(doc, path);
  const EditorDocument back = loadDocument(path);
  EXPECT_TRUE(sameField(back.field(), doc.field(), 0.0));
  EXPECT_FALSE(back.rules().has_value());  // the extra arc is no rules layout
  std::remove(path.c_str());
}

TEST(DocumentIo, SavedRulesLayoutGetsItsDimensionsBack) {
  for (const std::string& name : standardFieldNames()) {
    const std::string path = tempPath(name + ".yaml");
    saveDocument(standardDocument(name), path);
    const EditorDocument back = loadDocument(path);
    ASSERT_TRUE(back.isRulesShaped()) << name;
    EXPECT_NEAR(back.rules()->penalty_area_length,
                standardFieldDimensions(name).penalty_area_length, 1e-12);
    EXPECT_NEAR(back.rules()->corner_arc_radius, standardFieldDimensions(name).corner_arc_radius,
                1e-12);
    std::remove(path.c_str());
  }
  const std::string path = tempPath("small.yaml");
  saveDocument(EditorDocument(makeField(smallField())), path);
  EXPECT_NEAR(loadDocument(path).rules()->goal_area_length, 0.5, 1e-12);
  std::remove(path.c_str());
}

TEST(DocumentIo, SplJsonExportRoundTrip) {
  for (const FieldDimensions& dims :
       {standardFieldDimensions("spl"), standardFieldDimensions("spl2019"), smallField()}) {
    const EditorDocument doc(makeField(dims), dims);
    const std::string path = tempPath("field_dimensions.json");
    exportSplJson(doc, path);
    const EditorDocument back = loadDocument(path);
    ASSERT_TRUE(back.rules().has_value());
    // The JSON does not carry the name; everything else comes back exactly.
    FieldModel expected = doc.field();
    expected.name = back.field().name;
    EXPECT_TRUE(sameField(back.field(), expected, 0.0)) << dims.name;
    std::remove(path.c_str());
  }
}

TEST(DocumentIo, ExportRefusesFreeEditsAndNonSplRules) {
  EditorDocument doc = standardDocument("spl");
  doc = translateFeatures(doc, {doc.idAt(EditorKind::kMark, 0)}, Vector2d(0.1, 0)).after;
  EXPECT_THROW(exportSplJson(doc, tempPath("x.json")), FormatError);
  try {
    FieldDimensions wide = smallField();
    wide.line_width = 0.08;
    exportSplJson(EditorDocument(makeField(wide), wide), tempPath("x.json"));
    FAIL() << "8 cm lines are not SPL";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("field.lineWidth"), std::string::npos) << e.what();
  }
  EXPECT_THROW(loadDocument(tempPath("missing.yaml")), FormatError);
}

}  // namespace
}  // namespace houghloc::fieldmap
