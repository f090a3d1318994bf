// The pieces of houghloc-offline's localization modes that need no folder: the --global-only
// status rule, the hints.csv conversion and the summary's quantile.
#include <gtest/gtest.h>

#include "tools/offline/hint_conversion.h"
#include "tools/offline/mode_global_only.h"
#include "tools/offline/run_summary.h"

namespace houghloc {
namespace {

PoseHypothesis hypothesis(double x, double y, double theta, double weight) {
  PoseHypothesis h;
  h.field_T_robot = Pose2(x, y, theta);
  h.weight = weight;
  return h;
}

TEST(GlobalOnlyStatus, LostWithoutHypotheses) { EXPECT_STREQ(globalOnlyStatus({}), "LOST"); }

TEST(GlobalOnlyStatus, OneOrAClearWinnerIsTracking) {
  EXPECT_STREQ(globalOnlyStatus({hypothesis(1, 2, 0, 1.0)}), "TRACKING");
  EXPECT_STREQ(globalOnlyStatus({hypothesis(1, 2, 0, 0.7), hypothesis(-1, -2, M_PI, 0.3)}),
               "TRACKING");  // 0.3 < 0.5 * 0.7
}

TEST(GlobalOnlyStatus, ComparableDifferentPosesAreAmbiguous) {
  // The mirror pair of a point-symmetric field.
  EXPECT_STREQ(globalOnlyStatus({hypothesis(1, 2, 0, 0.5), hypothesis(-1, -2, M_PI, 0.5)}),
               "AMBIGUOUS");
  // Same place, headings 30 deg (0.52 rad) apart.
  EXPECT_STREQ(globalOnlyStatus({hypothesis(1, 2, 0, 0.5), hypothesis(1, 2, 0.52, 0.4)}),
               "AMBIGUOUS");
}

TEST(GlobalOnlyStatus, ComparableButSamePoseIsTracking) {
  EXPECT_STREQ(globalOnlyStatus({hypothesis(1, 2, 0, 0.5), hypothesis(1.2, 2.1, 0.1, 0.5)}),
               "TRACKING");
}

TEST(ConvertHints, PosesGetTheirCovarianceWithAFloor) {
  Recording rec;
  rec.folder = "/rec";
  rec.hints.push_back({1000, "RESET_TO", Pose2(1.0, -2.0, 0.5), 0.2, 0.0, 0.1});
  rec.hints.push_back({2000, "MIRROR", std::nullopt, 0, 0, 0});
  const std::vector<LocalizationHint> hints = convertHints(rec);
  ASSERT_EQ(hints.size(), 2u);
  EXPECT_EQ(hints[0].kind, HintKind::kResetTo);
  EXPECT_EQ(hints[0].t_us, 1000);
  ASSERT_EQ(hints[0].poses.size(), 1u);
  EXPECT_DOUBLE_EQ(hints[0].poses[0].mean.x, 1.0);
  EXPECT_DOUBLE_EQ(hints[0].poses[0].mean.theta, 0.5);
  EXPECT_DOUBLE_EQ(hints[0].poses[0].covariance(0, 0), 0.04);
  EXPECT_DOUBLE_EQ(hints[0].poses[0].covariance(1, 1), 1e-4);  // 0 raised to 1 cm
  EXPECT_DOUBLE_EQ(hints[0].poses[0].covariance(2, 2), 0.01);
  EXPECT_DOUBLE_EQ(hints[0].poses[0].covariance(0, 1), 0.0);
  EXPECT_EQ(hints[1].kind, HintKind::kMirror);
  EXPECT_TRUE(hints[1].poses.empty());
}

TEST(ConvertHints, AddWithoutPoseNamesTheFileAndTime) {
  Recording rec;
  rec.folder = "/rec";
  rec.hints.push_back({1234, "ADD", std::nullopt, 0, 0, 0});
  try {
    convertHints(rec);
    FAIL() << "no error";
  } catch (const RecordingError& e) {
    EXPECT_NE(std::string(e.what()).find("/rec/hints.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1234"), std::string::npos) << e.what();
  }
}

TEST(Quantile, NearestRank) {
  EXPECT_DOUBLE_EQ(quantile({}, 0.95), 0.0);
  EXPECT_DOUBLE_EQ(quantile({3.0}, 0.95), 3.0);
  std::vector<double> v;
  for (int i = 100; i >= 1; --i) v.push_back(i);
  EXPECT_DOUBLE_EQ(quantile(v, 0.95), 95.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.5), 50.0);
  EXPECT_DOUBLE_EQ(quantile(v, 1.0), 100.0);
}

}  // namespace
}  // namespace houghloc
