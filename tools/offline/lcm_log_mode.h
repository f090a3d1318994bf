#pragma once

#include "tools/offline/offline_options.h"

namespace houghloc {

/// houghloc-offline --lcm-log LOG (docs/offline.md): replays an lcm-logger log of houghloc-node
/// (replayLcmLog) with the field, config and cameras the node ran with, and writes poses.csv,
/// hypotheses.csv, the `tracking` section of metrics.json (when the log holds GROUND_TRUTH) and
/// trajectory.png into -o DIR (default LOG.houghloc/). Prints how far its poses are from the
/// logged HYPOTHESES. Returns the exit code; throws for input and output errors.
int runLcmLog(const OfflineOptions& options);

}  // namespace houghloc
