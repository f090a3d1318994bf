// Issue 6 targets for GlobalHoughLocalizer alone, on synthetic frames from seeds not used for
// tuning (tuning used seed 12345 / frame seeds 1000+).
#include <gtest/gtest.h>

#include <cmath>

#include "global_accuracy_fixture.h"

namespace houghloc {
namespace {

class GlobalAccuracy : public ::testing::TestWithParam<std::string> {};

/// Success measured at a99af39 (before the speed measures of docs/global-localization.md), per
/// field: GHL any on kid-wide and adult (seed 42), parallel-only frames within 3 sigma (seed
/// 43), in percent. A change may cost at most 0.5 percentage points of any of them.
struct Measured {
  double kid_wide, adult, parallel_only;
};
Measured measured(const std::string& field) {
  if (field == "msl") return {98.0, 97.25, 100.0};
  if (field == "kid") return {100.0, 100.0, 99.0};
  return {100.0, 100.0, 100.0};  // spl, spl2019, adult
}
constexpr double kMaxDropPp = 0.5;

TEST_P(GlobalAccuracy, WideViewsFindTheTruthAndAreAccurate) {
  for (const std::string view : {"kid-wide", "adult"}) {
    AccuracyRun run;
    run.field = GetParam();
    run.view = view;
    // MSL's large field gives the most varied views: 100 frames of seed 42 measured 94 / 97 %
    // (kid-wide / adult), 400 frames 98 / 97.2 %; the rate needs the larger sample.
    run.frames = run.field == "msl" ? 400 : 100;
    run.seed = 42;
    const AccuracySummary s = evaluateGlobal(run);
    std::cout << s.describe(run.field + "/" + view) << "\n";
    ASSERT_EQ(s.frames, run.frames);
    // Issue target: >= 95%, on every field. MSL met only with the field edge at long range
    // (FieldEdgeEvidence; without it 90-93%: lone arcs of the 4 m centre circle fit every
    // rotation about its centre). Weights were chosen on seed 7; see
    // docs/global-localization.md for the measured rates.
    EXPECT_GE(s.rate(s.ghl_any), 95.0) << view;
    const Measured m = measured(run.field);
    EXPECT_GE(s.rate(s.ghl_any), (view == "adult" ? m.adult : m.kid_wide) - kMaxDropPp) << view;
    EXPECT_LE(median(s.position_errors_m), 0.03) << view;
    EXPECT_LE(median(s.heading_errors_rad), 1.0 * M_PI / 180.0) << view;
  }
}

TEST_P(GlobalAccuracy, ParallelOnlyFramesKeepTheTruthWithinThreeSigma) {
  AccuracyRun run;
  run.field = GetParam();
  run.view = "nao-top";
  run.frames = 100;
  run.seed = 43;
  const ParallelSummary s = evaluateParallelOnly(run);
  std::cout << run.field << " parallel-only: " << s.within << "/" << s.frames
            << " within 3 sigma\n";
  ASSERT_GE(s.frames, 50);
  // Issue target: 99%, met on every field (measured 99-100%). Every map line of the seen
  // direction is tried for every heading, placed along its line by the scan (segment extents,
  // negative evidence), and a point-symmetric twin only takes a slot when there is room.
  EXPECT_GE(s.within, 0.99 * s.frames);
  EXPECT_GE(100.0 * s.within / s.frames, measured(run.field).parallel_only - kMaxDropPp);
}

INSTANTIATE_TEST_SUITE_P(StandardFields, GlobalAccuracy,
                         ::testing::Values("spl", "spl2019", "kid", "adult", "msl"));

}  // namespace
}  // namespace houghloc
