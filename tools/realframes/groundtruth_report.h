#pragma once

#include <vector>

#include "tools/realframes/groundtruth_frames.h"

namespace houghloc {

/// houghloc-real-report's section on the frames with a ground-truth pose: one row per frame,
/// houghloc beside the column-scan baseline.
void printGroundTruthFrames(const std::vector<GroundTruthFrameReport>& frames);

/// The --global-only check of one folder: one row per ground-truth frame and the hit counts.
void printGlobalCheck(const char* title, const std::vector<GlobalCheckFrame>& frames);

}  // namespace houghloc
