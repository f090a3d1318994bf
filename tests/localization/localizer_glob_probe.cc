#include <cstdio>
#include "field_models/standard_fields.h"
#include "localization/global_hough_localizer.h"
#include "tests/localization/localizer_test_support.h"
using namespace houghloc;
int main() {
  const FieldModel field = makeStandardField("spl");
  testing::ScenarioConfig config = testing::walkOn(field, 330, 13);
  std::vector<testing::ScenarioFrame> walk = testing::makeScenario(field, config);
  config.kidnap_frame = 180;
  config.kidnap_to = walk[120].field_T_robot * Pose2(0.0, 0.0, 0.6);
  const auto after = testing::makeScenario(field, config);
  GlobalHoughLocalizer g(field);
  for (int k = 180; k < 330; k += 3) {
    const auto hs = g.locate(after[k].points);
    int rank = -1;
    for (size_t i = 0; i < hs.size(); ++i) if (rank < 0 && testing::correctUpToSymmetry(hs[i].field_T_robot, after[k].field_T_robot)) rank = i;
    printf("%d two=%d n=%zu rank=%d w=%.3f kind0=%d", k, testing::seesTwoDirections(field, after[k].field_T_robot, after[k].points), hs.size(), rank, rank>=0?hs[rank].weight:0.0, hs.empty()?-1:(int)hs[0].kind);
    if (rank >= 0) printf(" kind=%d", (int)hs[rank].kind);
    printf("\n");
  }
}
