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
  double measured_pct;  ///< GHL any measured at a99af39; a change may cost at most 0.5 pp
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
  EXPECT_GE(s.rate(s.ghl_any), GetParam().measured_pct - 0.5);
  EXPECT_LE(median(s.position_errors_m), 0.03);
  EXPECT_LE(median(s.heading_errors_rad), 1.0 * M_PI / 180.0);
}

std::vector<Case> cases() {
  // GHL any (%) per field, views nao-top, nao-bottom, kid-wide, adult, measured at a99af39.
  const std::vector<std::pair<const char*, std::vector<double>>> measured = {
      {"spl", {100.0, 90.0, 100.0, 100.0}},  {"spl2019", {100.0, 85.0, 100.0, 100.0}},
      {"kid", {100.0, 90.0, 100.0, 100.0}},  {"adult", {100.0, 65.0, 100.0, 100.0}},
      {"msl", {91.67, 33.33, 100.0, 100.0}},
  };
  const char* views[] = {"nao-top", "nao-bottom", "kid-wide", "adult"};
  std::vector<Case> out;
  for (const auto& [field, pct] : measured) {
    const bool big = std::string(field) == "msl";
    for (int v = 0; v < 4; ++v) out.push_back({field, views[v], big ? 12 : 20, pct[v]});
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
