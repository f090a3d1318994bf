#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tools/realframes/mask_metrics.h"
#include "tools/realframes/real_frames.h"

namespace houghloc {

/// Per-folder counts of one detector (houghloc or the column-scan baseline).
struct DetectorCounts {
  long points = 0;     ///< over all frames
  int yes_empty = 0;   ///< frames showing lines (yes) without a point
  long no_points = 0;  ///< points on frames showing no line
  int no_frames_with_points = 0;
};

struct RealFolderSummary {
  std::string folder;
  int frames = 0, yes = 0, faint = 0, no = 0;
  DetectorCounts houghloc, baseline;
  std::vector<std::string> yes_empty_images;  ///< houghloc's, with the rejection reason
  std::vector<std::pair<std::string, int>> no_images_with_points;  ///< houghloc's, with the count
  std::optional<MaskMetrics> mask, baseline_mask;  ///< masked images only (one per folder)
};

/// Counts the outcomes; the mask metrics read <data_dir>/<folder>/labels/<image stem>.png.
RealFolderSummary summarizeRealFolder(const std::string& data_dir, const std::string& folder,
                                      const std::vector<RealFrameOutcome>& outcomes);

/// The table rows printed by houghloc-real-report and the real-frame test.
void printRealSummaryHeader();
void printRealSummary(const RealFolderSummary& s);

}  // namespace houghloc
