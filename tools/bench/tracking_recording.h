#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "field_models/ground_points.h"
#include "tools/offline/estimate_csv.h"
#include "tools/offline/offline_context.h"

namespace houghloc::bench {

/// A recorded folder (DESIGN §5.1) after vision: the ground points of every frame, computed once
/// with houghloc-offline's vision stage and config, so both localizers get the same input.
struct RecordedRun {
  OfflineContext context;            ///< recording, field, hints, configs
  std::vector<GroundPoints> points;  ///< per frame of [first_frame, end_frame)
  double mean_points = 0.0;          ///< points per frame
};

/// Reads DIR like `houghloc-offline DIR` (field from DIR/field.yaml) and runs vision on every
/// frame. The output folder loadOfflineContext() insists on is a scratch folder under the system
/// temp dir; nothing is written to DIR. Throws std::runtime_error / RecordingError naming the file.
RecordedRun loadRecordedRun(const std::string& dir);

/// What one localizer made of a recorded run: one estimate per frame (metrics input) and the
/// thread CPU time of each update, us.
struct RunOutput {
  std::vector<FrameEstimate> estimates;
  std::vector<double> cpu_us;
};

/// The Localizer facade exactly as houghloc-offline runs it (hints at their time).
RunOutput runLocalizer(const RecordedRun& run);

/// The reference MCL on the same points and odometry, reset to every RESET_TO hint at its time
/// (the start hint), other hint kinds ignored; without a hint at the first frame the particles
/// start uniform over the field.
RunOutput runMcl(const RecordedRun& run, std::uint32_t seed);

/// Runs both on DIR and prints the accuracy (DESIGN §5.3 tracking metrics, the metrics.json
/// definitions), the CPU time per update and the time ratio.
void compareOnRecording(const std::string& dir, std::uint32_t seed);

/// Thread CPU time, us: the machines are shared, so wall time would measure the neighbours.
double cpuNowUs();

}  // namespace houghloc::bench
