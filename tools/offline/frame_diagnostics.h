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
  /// "frames without points: ..." with one count per reason, and the frames scanned again with
  /// the pitch their image asked for (width_pitch.h, field_top_pitch.h).
  void print() const;

 private:
  CsvWriter spots_;
  std::array<int, kNumFrameRejections> counts_{};
  int image_pitch_frames_ = 0;  ///< frames scanned again with the pitch the image asked for
  int field_top_frames_ = 0;    ///< ... among them for field seen above the horizon
  double image_pitch_min_deg_ = 0.0, image_pitch_max_deg_ = 0.0;
};

}  // namespace houghloc
