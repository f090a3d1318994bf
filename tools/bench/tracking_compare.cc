// compareOnRecording(): the Localizer facade and the reference MCL on one rendered recording,
// scored with houghloc-offline's tracking metrics (metrics.json `tracking`, DESIGN §5.3).
#include <cstdio>
#include <stdexcept>

#include "tools/bench/tracking_recording.h"
#include "tools/offline/evaluation_frames.h"
#include "tools/offline/localization_evaluation.h"

namespace houghloc::bench {
namespace {

void printRow(const char* name, const TrackingMetrics& m, const RunOutput& out) {
  std::printf("%-22s %7.2f %7.2f %8.2f %7.1f%% %6d %6d %9.1f %9.1f\n", name,
              100.0 * m.median_position_error_m, 100.0 * m.p95_position_error_m,
              m.median_heading_error_deg, 100.0 * m.correct_rate, m.flips, m.first_correct_frame,
              median(out.cpu_us), percentile(out.cpu_us, 0.95));
}

}  // namespace

void compareOnRecording(const std::string& dir, std::uint32_t seed) {
  const RecordedRun run = loadRecordedRun(dir);
  const RunOutput localizer = runLocalizer(run);
  const RunOutput mcl = runMcl(run, seed);
  const auto m_localizer = computeTrackingMetrics(run.context, localizer.estimates);
  const auto m_mcl = computeTrackingMetrics(run.context, mcl.estimates);
  if (!m_localizer || !m_mcl) throw std::runtime_error(dir + ": no groundtruth.csv to score");

  std::printf(
      "Recording %s: %zu frames, %.0f ground points/frame (vision once, same points and "
      "odometry for both), MCL seed %u\n",
      dir.c_str(), run.points.size(), run.mean_points, seed);
  std::printf("%-22s %7s %7s %8s %8s %6s %6s %9s %9s\n", "method", "med cm", "p95 cm", "med deg",
              "correct", "flips", "first", "med us", "p95 us");
  printRow("Localizer (tracker)", *m_localizer, localizer);
  printRow("MCL 500 particles", *m_mcl, mcl);
  std::printf(
      "(metrics.json tracking: errors and flips from the first correct frame on; correct ="
      " within 0.10 m and 3 deg; first = first correct frame; us = thread CPU per update)\n");
  std::printf("Time ratio MCL / Localizer (median CPU per update): %.1fx; p95: %.1fx\n\n",
              median(mcl.cpu_us) / median(localizer.cpu_us),
              percentile(mcl.cpu_us, 0.95) / percentile(localizer.cpu_us, 0.95));
}

}  // namespace houghloc::bench
