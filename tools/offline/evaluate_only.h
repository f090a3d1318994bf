#pragma once

#include "tools/offline/offline_context.h"

namespace houghloc {

/// --evaluate-only: recomputes metrics.json and trajectory.png from OUT/poses.csv and
/// OUT/hypotheses.csv of an earlier run (a --global-only run when `global_only`) without
/// touching the images, and prints the metrics. The run itself ends with the same call, so the
/// metrics.json files are identical. Returns the exit code; throws naming the file at fault.
int runEvaluateOnly(const OfflineContext& context, bool global_only);

}  // namespace houghloc
