// houghloc-bench-tracking: one HypothesisTracker update (300 points, 4 hypotheses) against a
// reference Monte Carlo localization (500 particles) fed the same points and odometry, plus both
// accuracies on the same synthetic walk and on rendered recordings, so the time ratio is stated
// at a known accuracy.
//   houghloc-bench-tracking [--field=spl] [--frames=900] [--seed=11] [--recording=DIR[,DIR]]...
//                           [benchmark flags]
// --recording: a recorded folder (DESIGN §5.1) with ground truth; repeatable or a comma list.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "field_models/distance_grid.h"
#include "field_models/standard_fields.h"
#include "localization/hypothesis_tracker.h"
#include "tests/localization/tracking_scenario.h"
#include "tools/bench/mcl_baseline.h"
#include "tools/bench/tracking_recording.h"

namespace houghloc::bench {
namespace {

struct Options {
  std::string field = "spl";
  int frames = 900;
  std::uint32_t seed = 11;
  std::vector<std::string> recordings;
};

GaussianPose gaussian(const Pose2& pose, double sigma_m, double sigma_rad) {
  GaussianPose g;
  g.mean = pose;
  g.covariance =
      Eigen::Vector3d(sigma_m * sigma_m, sigma_m * sigma_m, sigma_rad * sigma_rad).asDiagonal();
  return g;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * (v.size() - 1) + 0.5)];
}

struct RunStats {
  std::vector<double> position_m, heading_deg, time_us;
  void add(const Pose2& estimate, const Pose2& truth, double us) {
    position_m.push_back((estimate.translation() - truth.translation()).norm());
    heading_deg.push_back(std::abs(angleDifference(estimate.theta, truth.theta)) * 180.0 / M_PI);
    time_us.push_back(us);
  }
  void print(const char* name) const {
    std::printf("%-22s %8.2f %8.2f %8.2f %8.3f %10.1f %10.1f\n", name,
                100.0 * percentile(position_m, 0.5), 100.0 * percentile(position_m, 0.95),
                100.0 * *std::max_element(position_m.begin(), position_m.end()),
                percentile(heading_deg, 0.5), percentile(time_us, 0.5), percentile(time_us, 0.95));
  }
};

/// Both methods on the same synthetic walk (10% odometry noise, 5% slip, 10% outliers), both
/// started from the same start hint (10 cm / 3 deg off).
void compareOnTrajectory(const Options& options) {
  const FieldModel field = makeStandardField(options.field);
  testing::ScenarioConfig config;
  config.frames = options.frames;
  config.seed = options.seed;
  config.half_extent_x_m = 0.33 * field.field_length;
  config.half_extent_y_m = 0.3 * field.field_width;
  config.max_range_m *= std::max(1.0, field.field_length / 9.0);
  const auto frames = testing::makeScenario(field, config);
  const Pose2 start(frames[0].field_T_robot.x + 0.07, frames[0].field_T_robot.y - 0.07,
                    frames[0].field_T_robot.theta + 0.05);

  HypothesisTracker tracker(field);
  LocalizationHint hint;
  hint.kind = HintKind::kResetTo;
  hint.poses = {gaussian(start, 0.1, 0.05)};
  tracker.applyHint(hint);
  const DistanceGrid grid(field);
  MonteCarloLocalizer mcl(field, grid, MclConfig{}, options.seed);
  mcl.reset(start, 0.1, 0.05);

  RunStats tracker_stats, mcl_stats;
  double points = 0.0;
  for (size_t k = 0; k < frames.size(); ++k) {
    const auto& f = frames[k];
    points += f.points.size();
    double t0 = cpuNowUs();
    tracker.update(f.t_us, f.odometry, f.points);
    tracker_stats.add(tracker.hypotheses().front().pose.mean, f.field_T_robot, cpuNowUs() - t0);
    const Pose2 motion = k == 0 ? Pose2() : frames[k - 1].odometry.inverse() * f.odometry;
    t0 = cpuNowUs();
    mcl.update(motion, f.points);
    mcl_stats.add(mcl.estimate(), f.field_T_robot, cpuNowUs() - t0);
  }
  std::printf("Trajectory: field %s, %zu frames at 30 fps, seed %u, %.0f points/frame on average\n",
              options.field.c_str(), frames.size(), options.seed, points / frames.size());
  std::printf("%-22s %8s %8s %8s %8s %10s %10s\n", "method", "med cm", "p95 cm", "max cm",
              "med deg", "med us", "p95 us");
  tracker_stats.print("HypothesisTracker");
  mcl_stats.print("MCL 500 particles");
  std::printf("Time ratio MCL / tracker (median CPU time per update): %.1fx\n\n",
              percentile(mcl_stats.time_us, 0.5) / percentile(tracker_stats.time_us, 0.5));
}

/// One frame with exactly 300 points seen from a pose with several line directions in view.
struct Fixture {
  FieldModel field = makeStandardField("spl");
  Pose2 truth{-2.8, 0.9, -2.6};
  GroundPoints points;
  Fixture() {
    testing::ScenarioConfig config;
    config.max_points = 273;  // + 10% outliers = 300
    points = testing::samplePoints(field, truth, 0.0, config, 5);
  }
};

void BM_TrackerUpdate300Points4Hypotheses(benchmark::State& state) {
  const Fixture fx;
  HypothesisTracker prepared(fx.field);
  LocalizationHint hint;
  hint.kind = HintKind::kResetTo;
  const Pose2 near(fx.truth.x + 0.05, fx.truth.y - 0.05, fx.truth.theta + 0.02);
  hint.poses = {gaussian(near, 0.1, 0.05), mirrored(gaussian(near, 0.1, 0.05)),
                gaussian(Pose2(1.0, 2.0, 1.0), 0.1, 0.05),
                gaussian(Pose2(-3.5, -1.0, -2.0), 0.1, 0.05)};
  prepared.applyHint(hint);
  prepared.predict(0, Pose2());
  if (fx.points.size() != 300 || prepared.hypotheses().size() != 4) {
    state.SkipWithError("fixture does not have 300 points and 4 hypotheses");
    return;
  }
  for (auto _ : state) {
    HypothesisTracker tracker = prepared;  // same 4 hypotheses every iteration
    tracker.update(33333, Pose2(0.01, 0.0, 0.0), fx.points);
    benchmark::DoNotOptimize(tracker.hypotheses().data());
  }
  state.counters["points"] = static_cast<double>(fx.points.size());
}
BENCHMARK(BM_TrackerUpdate300Points4Hypotheses)->Unit(benchmark::kMicrosecond);

void BM_MclUpdate300Points500Particles(benchmark::State& state) {
  const Fixture fx;
  const DistanceGrid grid(fx.field);
  MonteCarloLocalizer mcl(fx.field, grid, MclConfig{}, 1);
  mcl.reset(fx.truth, 0.1, 0.05);
  for (auto _ : state) {
    mcl.update(Pose2(0.01, 0.0, 0.0), fx.points);
    benchmark::DoNotOptimize(mcl.estimate());
  }
}
BENCHMARK(BM_MclUpdate300Points500Particles)->Unit(benchmark::kMicrosecond);

Options parseOptions(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--field=", 0) == 0) o.field = a.substr(8);
    if (a.rfind("--frames=", 0) == 0) o.frames = std::max(2, std::stoi(a.substr(9)));
    if (a.rfind("--seed=", 0) == 0) o.seed = static_cast<std::uint32_t>(std::stoul(a.substr(7)));
    if (a.rfind("--recording=", 0) == 0) {
      std::stringstream list(a.substr(12));
      for (std::string dir; std::getline(list, dir, ',');) {
        if (!dir.empty()) o.recordings.push_back(dir);
      }
    }
  }
  return o;
}

}  // namespace
}  // namespace houghloc::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);  // removes its own --benchmark_* flags
  const auto options = houghloc::bench::parseOptions(argc, argv);
  houghloc::bench::compareOnTrajectory(options);
  for (const std::string& dir : options.recordings) {
    try {
      houghloc::bench::compareOnRecording(dir, options.seed);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "houghloc-bench-tracking: %s\n", e.what());
      return 1;
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
