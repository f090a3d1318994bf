// The Qt editor on the offscreen platform: select and drag an endpoint with simulated mouse
// events, undo, redo, save, and compare the saved map with the expected one.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGraphicsItemGroup>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTimer>
#include <QtTest/QTest>
#include <cstdio>
#include <memory>

#include "field_models/field_yaml.h"
#include "field_models/pose2.h"
#include "tools/fieldmap/editor/editor_window.h"
#include "tools/fieldmap/editor_model/document_io.h"
#include "tools/fieldmap/editor_model/residuals.h"

namespace houghloc::fieldmap {
namespace {

class EditorWidget : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "editor_widget_test";
    static char* argv[] = {name, nullptr};
    app_ = new QApplication(argc, argv);
  }

  void SetUp() override {
    window_ = std::make_unique<EditorWindow>(standardDocument("spl"));
    window_->show();
    QApplication::processEvents();
    window_->view()->fitField();
    QApplication::processEvents();
  }

  /// Viewport pixel of a field point.
  QPoint pixel(double x, double y) const {
    return window_->view()->mapFromScene(toScene(Eigen::Vector2d(x, y)));
  }
  QWidget* viewport() const { return window_->view()->viewport(); }

  static QApplication* app_;
  std::unique_ptr<EditorWindow> window_;
};
QApplication* EditorWidget::app_ = nullptr;

TEST_F(EditorWidget, DragEndpointUndoRedoSave) {
  const EditorDocument original = window_->document();
  const FeatureId halfway = original.idAt(EditorKind::kSegment, 4);  // (0, -3) -> (0, 3)

  QTest::mouseClick(viewport(), Qt::LeftButton, {}, pixel(0.0, 1.5));  // select it
  ASSERT_EQ(window_->selection().size(), 1u);
  EXPECT_EQ(window_->selection()[0], halfway);

  // Drag its end handle from (0, 3) to (0.5, 2.5): no endpoint within 10 cm and 0.09 rad off
  // every line direction, so only the 5 cm grid snaps and the end lands exactly there.
  QTest::mousePress(viewport(), Qt::LeftButton, {}, pixel(0.0, 3.0));
  QTest::mouseMove(viewport(), pixel(0.3, 2.7));
  QTest::mouseMove(viewport(), pixel(0.5, 2.5));
  QTest::mouseRelease(viewport(), Qt::LeftButton, {}, pixel(0.5, 2.5));

  FieldModel expected = original.field();
  expected.segments[4].b = Eigen::Vector2d(0.5, 2.5);
  EXPECT_TRUE(sameField(window_->document().field(), expected, 1e-12));
  EXPECT_FALSE(window_->undoStack()->isClean());
  EXPECT_TRUE(window_->windowTitle().contains("*"));

  window_->undoStack()->undo();
  EXPECT_TRUE(sameField(window_->document().field(), original.field(), 0.0));
  window_->undoStack()->redo();
  EXPECT_TRUE(sameField(window_->document().field(), expected, 1e-12));

  const QString path = QString::fromStdString(::testing::TempDir()) + "/editor_widget.yaml";
  ASSERT_TRUE(window_->saveTo(path, true));
  EXPECT_TRUE(window_->undoStack()->isClean());
  EXPECT_TRUE(sameField(readFieldYaml(path.toStdString()), expected, 1e-12));
  std::remove(path.toLocal8Bit().constData());
}

TEST_F(EditorWidget, MoveSelectionAndValidationSelectsFeature) {
  const FeatureId mark = window_->document().idAt(EditorKind::kMark, 2);  // (3.2, 0)
  QTest::mouseClick(viewport(), Qt::LeftButton, {}, pixel(3.2, 0.0));
  ASSERT_EQ(window_->selection().size(), 1u);
  ASSERT_EQ(window_->selection()[0], mark);
  // Drag the mark itself 7 m along +x: outside the carpet (|x| <= 5.2).
  QTest::mousePress(viewport(), Qt::LeftButton, {}, pixel(3.2, 0.0));
  QTest::mouseMove(viewport(), pixel(4.0, 0.0));
  QTest::mouseRelease(viewport(), Qt::LeftButton, {}, pixel(3.2 + 7.0, 0.0));
  ASSERT_TRUE(window_->document().mark(mark).center.isApprox(Eigen::Vector2d(10.2, 0.0), 1e-9));

  window_->select({});
  QListWidget* list = window_->validationList();
  ASSERT_EQ(list->count(), 1);
  EXPECT_TRUE(list->item(0)->text().contains("outside"));
  QTest::mouseClick(list->viewport(), Qt::LeftButton, {},
                    list->visualItemRect(list->item(0)).center());
  ASSERT_EQ(window_->selection().size(), 1u);
  EXPECT_EQ(window_->selection()[0], mark);
  window_->undoStack()->setClean();  // no unsaved-changes prompt at teardown
}

TEST_F(EditorWidget, CheckPanelResidualsFollowThePose) {
  // The rendered penalty-area view of frame_check_test, checked in the window at its true pose.
  window_->openCheck(HOUGHLOC_CHECK_FIXTURE, 1);
  const ResidualReport& report = window_->checkPanel()->report();
  ASSERT_GT(report.overall.count, 50);
  EXPECT_LT(report.overall.mean_m, 0.02);
  EXPECT_FALSE(window_->view()->overlay()->childItems().isEmpty());
  // Shift+drag the pose 0.3 m along +x: the points on the lines across x (goal line, area
  // fronts) move 0.3 m off them.
  QTest::mousePress(viewport(), Qt::LeftButton, Qt::ShiftModifier, pixel(0.0, 0.0));
  QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::ShiftModifier, pixel(0.3, 0.0));
  EXPECT_GT(window_->checkPanel()->report().overall.mean_m, 0.15);
  EXPECT_TRUE(window_->undoStack()->isClean());  // the pose is no map edit
}

TEST_F(EditorWidget, LocalizeButtonFindsTheTrueOrMirrorPose) {
  window_->openCheck(HOUGHLOC_CHECK_FIXTURE, 1);
  CheckPanel* panel = window_->checkPanel();
  // The reference: the fixture's ground truth, and the localizer's poses run outside the panel.
  FrameSource source(HOUGHLOC_CHECK_FIXTURE);
  const CheckFrame reference = source.frame(1, &window_->document().field());
  ASSERT_TRUE(reference.ground_truth.has_value());
  ASSERT_FALSE(reference.located.empty());
  const Pose2 truth = *reference.ground_truth;
  const Pose2 mirror(-truth.x, -truth.y, truth.theta + M_PI);

  auto* button = panel->findChild<QPushButton*>("localize");
  ASSERT_NE(button, nullptr);
  panel->nudgePose(Eigen::Vector2d(0.8, -0.5), 0.4);  // start far off
  ASSERT_GT(panel->report().overall.mean_m, 0.15);
  // Two presses: the best pose, then the next of the localizer's poses.
  std::vector<Pose2> shown;
  for (int press = 0; press < 2; ++press) {
    QTest::mouseClick(button, Qt::LeftButton);
    const Pose2 p = panel->pose();
    shown.push_back(p);
    bool from_localizer = false;  // the form rounds to mm and 0.001 deg
    for (const Pose2& q : reference.located) {
      from_localizer |= (p.translation() - q.translation()).norm() < 2e-3 &&
                        std::abs(angleDifference(p.theta, q.theta)) < 1e-4;
    }
    EXPECT_TRUE(from_localizer) << "press " << press + 1;
    double off_m = 1e9;
    for (const Pose2& good : {truth, mirror}) {
      if (std::abs(angleDifference(p.theta, good.theta)) < 3.0 * M_PI / 180.0) {
        off_m = std::min(off_m, (p.translation() - good.translation()).norm());
      }
    }
    std::printf(
        "press %d of %zu poses: (%.3f, %.3f, %.2f deg), %.3f m off the truth or twin, "
        "residual mean %.4f m\n",
        press + 1, reference.located.size(), p.x, p.y, p.theta * 180.0 / M_PI, off_m,
        panel->report().overall.mean_m);
    if (press == 0) {  // the best pose
      EXPECT_LT(off_m, 0.10);
      EXPECT_LT(panel->report().overall.mean_m, 0.02);
    }
  }
  if (reference.located.size() > 1) {
    EXPECT_GT((shown[0].translation() - shown[1].translation()).norm() +
                  std::abs(angleDifference(shown[0].theta, shown[1].theta)),
              1e-3);  // the second press cycled on
  }
  EXPECT_TRUE(window_->undoStack()->isClean());  // the pose is no map edit
}

/// Answers the next modal message box with `button` once it is open.
void answerPrompt(QMessageBox::StandardButton button, QString* text) {
  QTimer::singleShot(0, [button, text] {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (!box) return;
    *text = box->text();
    box->button(button)->click();
  });
}

TEST_F(EditorWidget, UnsavedChangesPromptOnQuit) {
  window_->apply(
      deleteFeatures(window_->document(), {window_->document().idAt(EditorKind::kMark, 0)}));
  QString text;
  answerPrompt(QMessageBox::Cancel, &text);
  EXPECT_FALSE(window_->close());  // cancelled: stays open
  EXPECT_TRUE(text.contains("unsaved"));
  EXPECT_TRUE(window_->isVisible());
  text.clear();
  answerPrompt(QMessageBox::Discard, &text);
  EXPECT_TRUE(window_->close());
  EXPECT_TRUE(text.contains("unsaved"));
  // A saved (clean) map closes without asking.
  window_ = std::make_unique<EditorWindow>(standardDocument("spl"));
  window_->show();
  EXPECT_TRUE(window_->close());
}

/// Types a value into the dimensions panel's spin box with this label, as a user would.
void typeDimension(QWidget* window, const QString& label, const QString& value) {
  for (QFormLayout* form : window->findChildren<QFormLayout*>()) {
    for (int row = 0; row < form->rowCount(); ++row) {
      auto* name = qobject_cast<QLabel*>(form->itemAt(row, QFormLayout::LabelRole)->widget());
      if (!name || name->text() != label) continue;
      auto* box =
          qobject_cast<QDoubleSpinBox*>(form->itemAt(row, QFormLayout::FieldRole)->widget());
      box->selectAll();
      QTest::keyClicks(box, value);
      QTest::keyClick(box, Qt::Key_Enter);
      return;
    }
  }
  FAIL() << "no field " << label.toStdString();
}

TEST_F(EditorWidget, DimensionsPanelBuildsSmallField) {
  // The lab field of docs/editor.md: 7.5 x 5 m with a 0.5 m goal area, SPL otherwise.
  auto* name = window_->findChild<QLineEdit*>("map_name");
  ASSERT_NE(name, nullptr);
  name->selectAll();
  QTest::keyClicks(name, "lab 7.5 x 5");
  typeDimension(window_.get(), "length (m)", "7.5");
  typeDimension(window_.get(), "width (m)", "5");
  typeDimension(window_.get(), "goal area length (m)", "0.5");
  QPushButton* regenerate = nullptr;
  for (QPushButton* b : window_->findChildren<QPushButton*>())
    if (b->text() == "Regenerate rules layout") regenerate = b;
  ASSERT_NE(regenerate, nullptr);
  QTest::mouseClick(regenerate, Qt::LeftButton);

  FieldDimensions expected = standardFieldDimensions("spl");
  expected.name = "lab 7.5 x 5";
  expected.length = 7.5;
  expected.width = 5.0;
  expected.goal_area_length = 0.5;
  EXPECT_TRUE(sameField(window_->document().field(), makeField(expected), 1e-12));
  EXPECT_TRUE(window_->document().isRulesShaped());
  EXPECT_EQ(window_->validationList()->item(0)->text(), "map is valid");

  const QString path = QString::fromStdString(::testing::TempDir()) + "/lab_7.5x5.yaml";
  ASSERT_TRUE(window_->saveTo(path, true));
  EXPECT_TRUE(sameField(readFieldYaml(path.toStdString()), makeField(expected), 1e-12));
}

}  // namespace
}  // namespace houghloc::fieldmap
