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
  /// "frames without points: ..." with one count per reason, and the frames processed with the
  /// pitch their image asked for (field_top_pitch.h, width_pitch.h).
  void print() const;

 private:
  CsvWriter spots_;
  std::array<int, kNumFrameRejections> counts_{};
  /// Frames processed with a pitch offset the image asked for, and the offsets' range.
  struct PitchOffsets {
    int frames = 0;
    double min_deg = 0.0, max_deg = 0.0;
    void add(double offset_rad);  ///< 0: none
  };
  PitchOffsets field_top_pitch_, width_pitch_;
};

}  // namespace houghloc
