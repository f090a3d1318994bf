#include "tools/offline/evaluate_only.h"

#include <cstdio>

#include "tools/offline/localization_evaluation.h"

namespace houghloc {

int runEvaluateOnly(const OfflineContext& context, bool global_only) {
  const EvaluationResult result = evaluateOutputs(context, global_only);
  std::printf("houghloc-offline --evaluate-only%s -> %s\n", global_only ? " --global-only" : "",
              context.out_dir.c_str());
  printEvaluation(result);
  return 0;
}

}  // namespace houghloc
