// Issue 6: GHL finds a hypothesis correct up to symmetry at least as often as the exhaustive
// grid search finds one among its 12 best distinct optima (within 1 percentage point), on the
// same frames (seeds not used for tuning).
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>

#include "global_accuracy_fixture.h"

namespace houghloc {
namespace {

struct Case {
  std::string field;
  std::string view;
  int frames;
};

// Readable test parameters in ctest output (instead of the struct's bytes).
void PrintTo(const Case& c, std::ostream* os) {
  *os << c.field << "/" << c.view << ", " << c.frames << " frames";
}

class GlobalVsGrid : public ::testing::TestWithParam<Case> {};

TEST_P(GlobalVsGrid, AtLeastAsOftenAsTheExhaustiveSearch) {
  AccuracyRun run;
  run.field = GetParam().field;
  run.view = GetParam().view;
  run.frames = GetParam().frames;
  run.seed = 2024;
  run.grid = true;
  run.positive_only = true;
  const AccuracySummary s = evaluateGlobal(run);
  std::cout << s.describe(run.field + "/" + run.view) << "\n";
  ASSERT_EQ(s.frames, run.frames);
  // Negative evidence must not lose frames that the positive-only variant finds.
  EXPECT_GE(s.ghl_any, s.ghl_positive_any);
  // Issue target: within 1 percentage point of the exhaustive search, met on every row (the
  // adult/nao-bottom frame with a short arc of the 3 m circle counts since circles are accepted
  // from a shorter arc for large radii, docs/global-localization.md).
  EXPECT_GE(s.rate(s.ghl_any), s.rate(s.grid_any) - 1.0);
  EXPECT_LE(median(s.position_errors_m), 0.03);
  EXPECT_LE(median(s.heading_errors_rad), 1.0 * M_PI / 180.0);
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const char* field : {"spl", "spl2019", "kid", "adult", "msl"}) {
    const bool big = std::string(field) == "msl";
    for (const char* view : {"nao-top", "nao-bottom", "kid-wide", "adult"}) {
      out.push_back({field, view, big ? 12 : 20});
    }
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(FieldsAndViews, GlobalVsGrid, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.field + "_" + info.param.view;
                           for (char& c : name)
                             c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

}  // namespace
}  // namespace houghloc
