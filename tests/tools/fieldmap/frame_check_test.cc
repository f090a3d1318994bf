// The editor's check against reality on a rendered frame: at the true pose the true map fits
// within 2 cm on average; a map whose penalty area is 20 cm too long shows it on that line.
#include "tools/fieldmap/frame_check/frame_check.h"

#include <gtest/gtest.h>

#include <cmath>

#include "field_models/standard_fields.h"
#include "tools/fieldmap/editor_model/residuals.h"

namespace houghloc::fieldmap {
namespace {

const ResidualStats* statsFor(const ResidualReport& report, FeatureKind kind, int index) {
  for (const FeatureResidual& f : report.features)
    if (f.feature.kind == kind && f.feature.index == index) return &f.stats;
  return nullptr;
}

TEST(FrameCheck, TrueMapFitsAndLongPenaltyAreaShows) {
  FrameSource source(HOUGHLOC_CHECK_FIXTURE);
  ASSERT_EQ(source.frameCount(), 2);
  const CheckFrame frame = source.frame(1);
  ASSERT_TRUE(frame.ground_truth.has_value());
  ASSERT_GT(frame.points_robot.size(), 50u);

  const FieldModel truth = makeStandardField("spl");
  const ResidualReport fit = computeResiduals(truth, frame.points_robot, *frame.ground_truth);
  EXPECT_LT(fit.overall.mean_m, 0.02);
  EXPECT_GT(fit.overall.count, 50);
  // The opponent penalty area's front line (segments[14], x = 2.85) is in view.
  const ResidualStats* front = statsFor(fit, FeatureKind::kSegment, 14);
  ASSERT_NE(front, nullptr);
  EXPECT_GT(front->count, 10);
  std::printf(
      "true map: overall mean %.4f m p95 %.4f m (%d points, %d unmatched); "
      "penalty front line mean %.4f m\n",
      fit.overall.mean_m, fit.overall.p95_m, fit.overall.count, fit.unmatched, front->mean_m);

  FieldDimensions wrong = standardFieldDimensions("spl");
  wrong.penalty_area_length += 0.20;
  const ResidualReport off =
      computeResiduals(makeField(wrong), frame.points_robot, *frame.ground_truth);
  const ResidualStats* wrong_front = statsFor(off, FeatureKind::kSegment, 14);
  ASSERT_NE(wrong_front, nullptr);
  EXPECT_GE(wrong_front->mean_m, 0.15);
  std::printf("penalty area 20 cm long: front line mean %.4f m p95 %.4f m (%d points)\n",
              wrong_front->mean_m, wrong_front->p95_m, wrong_front->count);

  EXPECT_THROW(source.frame(2), RecordingError);
}

TEST(FrameCheck, TheLocalizerPlacesTheFrameOnTheMap) {
  FrameSource source(HOUGHLOC_CHECK_FIXTURE);
  const FieldModel truth = makeStandardField("spl");
  EXPECT_TRUE(source.frame(1).located.empty());  // without a map only vision runs
  const CheckFrame frame = source.frame(1, &truth);
  ASSERT_TRUE(frame.ground_truth.has_value());
  ASSERT_FALSE(frame.located.empty());
  // The field is point-symmetric: the truth or its mirror twin is among the poses.
  const Pose2& t = *frame.ground_truth;
  const Pose2 mirror(-t.x, -t.y, t.theta + M_PI);
  double nearest_m = 1e9;
  for (const Pose2& p : frame.located) {
    for (const Pose2& want : {t, mirror}) {
      if (std::abs(angleDifference(p.theta, want.theta)) < 3.0 * M_PI / 180.0) {
        nearest_m = std::min(nearest_m, (p.translation() - want.translation()).norm());
      }
    }
  }
  EXPECT_LT(nearest_m, 0.10);
}

}  // namespace
}  // namespace houghloc::fieldmap
