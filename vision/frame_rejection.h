#pragma once

#include "vision/vision_pipeline.h"

namespace houghloc {

/// The stage that left a frame without ground points, for a team at a new venue to see at once
/// what went wrong (the offline summary counts them, the overlay names them).
enum class FrameRejection {
  kNone,               ///< the frame gave points
  kNoFieldColor,       ///< no turf colour found: nothing is scanned
  kNoBoundary,         ///< turf colour found, but no field region below the horizon
  kNoCandidates,       ///< nothing on the scan grid rose above the contrast threshold
  kTooWide,            ///< most candidates wider than the width model allows
  kTooNarrow,          ///< ... narrower
  kNotTurfBounded,     ///< ... without turf on both sides
  kNotWhite,           ///< ... too saturated for paint
  kSoftEdge,           ///< ... with edges ramping like round bars
  kCompactBlob,        ///< ... whose run does not go on beside them (ball, feet)
  kOnBall,             ///< ... lying on a ball
  kNotProjected,       ///< spots found, all beyond the range or above the horizon
  kDroppedNearBorder,  ///< spots found, all dropped near the boundary or on the own feet
  kIsolated,           ///< spots found, the rest of them each without another near it
};

constexpr int kNumFrameRejections = 14;

/// Why this frame has no points (kNone when it has some).
FrameRejection classifyFrame(const VisionResult& result);

/// Short name for summaries and overlays, e.g. "no field colour".
const char* frameRejectionName(FrameRejection rejection);

}  // namespace houghloc
