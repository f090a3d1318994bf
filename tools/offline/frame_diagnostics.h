#pragma once

#include <array>
#include <string>

#include "tools/recording/csv.h"
#include "tools/recording/recording.h"
#include "vision/frame_rejection.h"

namespace houghloc {

/// --vision-only's per-frame diagnostics: spots.csv (every accepted image spot, whether it
/// reached the ground) and the count of frames without points per FrameRejection.
class FrameDiagnostics {
 public:
  /// Throws RecordingError when spots.csv cannot be created.
  explicit FrameDiagnostics(const std::string& spots_csv);

  /// One frame: its spots (projected with the pose the pipeline used) and its rejection.
  void add(const FrameRecord& frame, const CameraIntrinsics& intrinsics, const VisionResult& result,
           const GroundProjectionConfig& projection);
  void close() { spots_.close(); }
  /// "frames without points: ..." with one count per reason, and the frames whose pitch was
  /// fitted to their candidates' widths (width_pitch.h).
  void print() const;

 private:
  CsvWriter spots_;
  std::array<int, kNumFrameRejections> counts_{};
  int width_pitch_frames_ = 0;  ///< frames scanned again with a pitch fitted to line widths
  double width_pitch_min_deg_ = 0.0, width_pitch_max_deg_ = 0.0;
};

}  // namespace houghloc
