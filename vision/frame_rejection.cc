#include "vision/frame_rejection.h"

#include <algorithm>
#include <array>
#include <utility>

namespace houghloc {

FrameRejection classifyFrame(const VisionResult& result) {
  if (!result.ground.points.empty()) return FrameRejection::kNone;
  const VisionDiagnostics& d = result.diagnostics;
  if (!d.field_color.valid) return FrameRejection::kNoFieldColor;
  if (!result.boundary.found) return FrameRejection::kNoBoundary;
  const LineSpotStats& s = d.spot_stats;
  if (d.num_spots == 0) {
    if (s.candidates == 0) return FrameRejection::kNoCandidates;
    const std::array<std::pair<int, FrameRejection>, 7> classes = {{
        {s.too_wide, FrameRejection::kTooWide},
        {s.too_narrow, FrameRejection::kTooNarrow},
        {s.not_green_bounded, FrameRejection::kNotTurfBounded},
        {s.not_white, FrameRejection::kNotWhite},
        {s.soft_edge, FrameRejection::kSoftEdge},
        {s.compact_blob, FrameRejection::kCompactBlob},
        {s.on_ball, FrameRejection::kOnBall},
    }};
    return std::max_element(classes.begin(), classes.end(),
                            [](const auto& a, const auto& b) { return a.first < b.first; })
        ->second;
  }
  const int dropped = d.dropped_near_boundary + d.dropped_on_own_body;
  if (dropped >= d.num_spots) return FrameRejection::kDroppedNearBorder;
  if (dropped + d.dropped_isolated >= d.num_spots) return FrameRejection::kIsolated;
  return FrameRejection::kNotProjected;
}

const char* frameRejectionName(FrameRejection rejection) {
  switch (rejection) {
    case FrameRejection::kNone:
      return "points";
    case FrameRejection::kNoFieldColor:
      return "no field colour";
    case FrameRejection::kNoBoundary:
      return "no field region";
    case FrameRejection::kNoCandidates:
      return "no candidate above the contrast threshold";
    case FrameRejection::kTooWide:
      return "candidates too wide";
    case FrameRejection::kTooNarrow:
      return "candidates too narrow";
    case FrameRejection::kNotTurfBounded:
      return "candidates not turf-bounded";
    case FrameRejection::kNotWhite:
      return "candidates not white";
    case FrameRejection::kSoftEdge:
      return "candidates with soft edges";
    case FrameRejection::kCompactBlob:
      return "candidates not going on beside them";
    case FrameRejection::kOnBall:
      return "candidates on a ball";
    case FrameRejection::kIsolated:
      return "spots each without another near it";
    case FrameRejection::kNotProjected:
      return "spots beyond range or above the horizon";
    case FrameRejection::kDroppedNearBorder:
      return "spots dropped near the boundary or feet";
  }
  return "unknown";
}

}  // namespace houghloc
