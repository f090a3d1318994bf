#pragma once

#include "tools/offline/offline_context.h"

namespace houghloc {

/// --vision-only: runs VisionPipeline on every frame in range, writes points.csv, timing.csv,
/// the `vision` section of metrics.json (when ground truth, truth/visible.csv and a field exist)
/// and, with --overlay, OUT/overlay/<frame>.png; prints a summary table. Returns the exit code.
/// Throws for input errors (std::runtime_error naming the file).
int runVisionOnly(const OfflineContext& context);

}  // namespace houghloc
