#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "localization/gaussian_pose.h"

namespace houghloc {

/// One frame of localization output as poses.csv and hypotheses.csv hold it (DESIGN §5.2).
struct FrameEstimate {
  std::int64_t t_us = 0;
  std::string status;                    ///< INITIALIZING, TRACKING, AMBIGUOUS or LOST
  std::vector<GaussianPose> hypotheses;  ///< rank order, best first; may be empty
  /// Weight of the best pose's mirror twin (mirrorTwinWeight() with the tracker's default
  /// mirror tolerances, 0.3 m / 0.3 rad): poses.csv `twin_weight`.
  double twinWeight() const;
};

/// Writes OUT/poses.csv and OUT/hypotheses.csv with the headers of DESIGN §5.2, poses.csv with a
/// last column `twin_weight` (a frame without hypotheses gets a poses.csv row with empty pose
/// fields, num_hypotheses 0 and twin_weight 0).
/// Numbers are written so that readFrameEstimates() gets the same doubles back.
/// One estimate per time: when consecutive estimates share a t_us (two cameras exposed together,
/// or one camera whose clock repeated a time), only the last, which has seen every one of those
/// frames, is written.
class EstimateCsvWriter {
 public:
  /// Throws RecordingError naming the file when it cannot be created.
  explicit EstimateCsvWriter(const std::string& out_dir);
  void write(const FrameEstimate& estimate);
  /// Writes the last estimate held back; throws RecordingError naming the file when writing
  /// failed.
  void close();

 private:
  struct Files;
  void writeRows(const FrameEstimate& estimate);
  std::shared_ptr<Files> files_;
};

/// Reads OUT/poses.csv and OUT/hypotheses.csv back (for --evaluate-only). Throws RecordingError
/// naming file and line for a missing file, a bad header, a malformed row or a hypotheses.csv
/// row whose t_us has no poses.csv row.
std::vector<FrameEstimate> readFrameEstimates(const std::string& out_dir);

}  // namespace houghloc
