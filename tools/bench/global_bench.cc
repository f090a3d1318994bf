// Benchmarks of global Hough localization (issue 6), one core:
//   locate() with 100 / 300 / 1000 points on the SPL and MSL maps;
//   step 1 (HoughTransform) vs cv::HoughLinesPointSet on the same points;
//   locate() vs the exhaustive grid search on the same frames, with success rates;
// then a summary of time ratios and success rates side by side: min / median CPU time per
// field x points (growth with points and with map size), grid-search and step-1 ratios, and the
// worst frame (median, p99, maximum) over 500 random-pose frames of every field preset.
// `--benchmark_filter=NONE` prints the summary alone, `--no_summary` leaves it out,
// `--profile=msl/100` or `--profile=worst/msl` only runs locate() on those frames (profiling).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <random>
#include <string>
#include <vector>

#include "field_models/standard_fields.h"
#include "localization/global_hough_localizer.h"
#include "tools/baselines/grid_search.h"
#include "tools/synthetic/synthetic_ground_points.h"

namespace houghloc {
namespace {

constexpr int kFrames = 8;  // frames cycled through per benchmark

struct Frame {
  GroundPoints ground;
  Pose2 truth;
};

const FieldModel& field(const std::string& name) {
  static std::map<std::string, FieldModel> fields;
  auto it = fields.find(name);
  if (it == fields.end()) it = fields.emplace(name, makeStandardField(name)).first;
  return it->second;
}

const GlobalHoughLocalizer& localizer(const std::string& name) {
  static std::map<std::string, std::unique_ptr<GlobalHoughLocalizer>> cache;
  auto& l = cache[name];
  if (!l) l = std::make_unique<GlobalHoughLocalizer>(field(name));
  return *l;
}

const GridSearchLocalizer& gridSearch(const std::string& name) {
  static std::map<std::string, std::unique_ptr<GridSearchLocalizer>> cache;
  auto& g = cache[name];
  if (!g) g = std::make_unique<GridSearchLocalizer>(field(name));
  return *g;
}

/// The most points a benchmark row asks for. Every row draws its frames from those with at least
/// this many, so the rows of a field differ in the number of points only, not in the frames.
constexpr int kMostPoints = 1000;

/// Frames with two directions in view (kid-wide view), exactly `points` points each (even
/// subsample of a dense frame of at least kMostPoints points).
const std::vector<Frame>& frames(const std::string& name, int points) {
  static std::map<std::pair<std::string, int>, std::vector<Frame>> cache;
  auto& out = cache[{name, points}];
  if (!out.empty()) return out;
  std::mt19937_64 rng(99);
  for (int k = 0; static_cast<int>(out.size()) < kFrames && k < 1000; ++k) {
    SyntheticConfig config;
    config.view = viewModel("kid-wide");
    config.point_spacing_m = 0.01;
    config.seed = 500 + k;
    const SyntheticFrame f = generateFrame(field(name), randomPose(field(name), 0.3, rng), config);
    const int dense = std::max(points, kMostPoints);
    if (!hasTwoDirections(f) || static_cast<int>(f.ground.size()) < dense) continue;
    Frame frame{f.ground, f.field_T_robot};
    frame.ground.points.clear();
    const double stride = static_cast<double>(f.ground.size()) / points;
    for (int i = 0; i < points; ++i)
      frame.ground.points.push_back(f.ground.points[static_cast<std::size_t>(i * stride)]);
    out.push_back(frame);
  }
  return out;
}

bool correct(const Pose2& p, const Pose2& truth) {
  for (const Pose2& t : {truth, Pose2(-truth.x, -truth.y, truth.theta + M_PI)}) {
    if ((p.translation() - t.translation()).norm() <= 0.10 &&
        std::abs(angleDifference(p.theta, t.theta)) <= 3.0 * M_PI / 180.0) {
      return true;
    }
  }
  return false;
}

const std::vector<std::string> kFields = {"spl", "msl"};

void BM_Locate(benchmark::State& state) {
  const std::string name = kFields[state.range(0)];
  const auto& fs = frames(name, static_cast<int>(state.range(1)));
  const auto& ghl = localizer(name);
  int k = 0, found = 0, runs = 0;
  for (auto _ : state) {
    const Frame& f = fs[k++ % fs.size()];
    const auto hs = ghl.locate(f.ground);
    benchmark::DoNotOptimize(hs.data());
    for (const auto& h : hs) {
      if (correct(h.field_T_robot, f.truth)) {
        ++found;
        break;
      }
    }
    ++runs;
  }
  state.SetLabel(name);
  state.counters["points"] = static_cast<double>(state.range(1));
  state.counters["success_pct"] = 100.0 * found / std::max(1, runs);
}
BENCHMARK(BM_Locate)->ArgsProduct({{0, 1}, {100, 300, 1000}})->Unit(benchmark::kMillisecond);

void BM_GridSearch(benchmark::State& state) {
  const std::string name = kFields[state.range(0)];
  const auto& fs = frames(name, 300);
  const auto& grid = gridSearch(name);
  int k = 0, found = 0, runs = 0;
  for (auto _ : state) {
    const Frame& f = fs[k++ % fs.size()];
    const auto optima = grid.locate(f.ground);
    for (const auto& o : optima) {
      if (correct(o.field_T_robot, f.truth)) {
        ++found;
        break;
      }
    }
    ++runs;
  }
  state.SetLabel(name);
  state.counters["points"] = 300;
  state.counters["success_pct"] = 100.0 * found / std::max(1, runs);
}
BENCHMARK(BM_GridSearch)->Arg(0)->Arg(1)->Iterations(kFrames)->Unit(benchmark::kMillisecond);

/// Step 1 alone: our weighted transform with the localizer's resolution (1 deg, 3 cm).
void BM_Step1HoughTransform(benchmark::State& state) {
  const auto& fs = frames("spl", static_cast<int>(state.range(0)));
  const auto& ghl = localizer("spl");
  int k = 0;
  for (auto _ : state) {
    const WeightedPoints pts = ghl.preparePoints(fs[k++ % fs.size()].ground);
    const HoughTransform ht = ghl.sensorTransform(pts);
    benchmark::DoNotOptimize(ht.column(0));
  }
  state.counters["points"] = static_cast<double>(state.range(0));
}
BENCHMARK(BM_Step1HoughTransform)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMicrosecond);

/// The OpenCV baseline for step 1: the same accumulator resolution and rho range, plus OpenCV's
/// own peak extraction (up to 20 lines).
void BM_Step1CvHoughLinesPointSet(benchmark::State& state) {
  const auto& fs = frames("spl", static_cast<int>(state.range(0)));
  int k = 0;
  for (auto _ : state) {
    const GroundPoints& g = fs[k++ % fs.size()].ground;
    std::vector<cv::Point2f> pts;
    double range = 0.03;
    for (const auto& p : g.points) {
      pts.emplace_back(static_cast<float>(p.p_robot.x()), static_cast<float>(p.p_robot.y()));
      range = std::max(range, p.p_robot.norm());
    }
    cv::Mat lines;
    cv::HoughLinesPointSet(pts, lines, 20, 5, -range, range, 0.03, 0.0, CV_PI, CV_PI / 180.0);
    benchmark::DoNotOptimize(lines.data);
  }
  state.counters["points"] = static_cast<double>(state.range(0));
}
BENCHMARK(BM_Step1CvHoughLinesPointSet)
    ->Arg(100)
    ->Arg(300)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond);

double cpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/// Mean CPU ms per locate() over all frames, repeated: min and median of the repetitions (the
/// machine may be shared; the minimum is the least disturbed).
struct Timing {
  double min_ms = 0.0, median_ms = 0.0;
  int ok = 0;
};

Timing timeLocate(const std::string& name, int points, int repetitions) {
  const auto& fs = frames(name, points);
  Timing out;
  std::vector<double> ms;
  for (int rep = 0; rep < repetitions; ++rep) {
    double t = 0.0;
    for (const Frame& f : fs) {
      const double t0 = cpuSeconds();
      const auto hs = localizer(name).locate(f.ground);
      t += cpuSeconds() - t0;
      if (rep > 0) continue;
      for (const auto& h : hs) {
        if (correct(h.field_T_robot, f.truth)) {
          ++out.ok;
          break;
        }
      }
    }
    ms.push_back(1e3 * t / fs.size());
  }
  std::sort(ms.begin(), ms.end());
  out.min_ms = ms.front();
  out.median_ms = ms[ms.size() / 2];
  return out;
}

double lineLength(const FieldModel& f) {
  double sum = 0.0;
  for (const auto& s : f.segments) sum += s.length();
  for (const auto& a : f.arcs) sum += a.length();
  return sum;
}

/// Side-by-side summary on the same frames (CPU time, so other load on the machine matters less):
/// how locate() grows with the number of points and with the map, and the ratios against the
/// baselines (grid search for the whole, cv::HoughLinesPointSet for step 1).
void printSummary() {
  constexpr int kRepetitions = 7;
  std::printf(
      "\nsummary: kid-wide frames with two directions, %d per field; CPU ms per locate(),\n"
      "min / median of %d repetitions over all frames\n",
      kFrames, kRepetitions);
  for (const std::string& name : kFields) {
    const FieldModel& f = field(name);
    std::printf("  %-4s carpet %.1f x %.1f m, %.0f m of lines and arcs, %zu segments, %zu arcs\n",
                name.c_str(), 2.0 * f.outerHalfLength(), 2.0 * f.outerHalfWidth(), lineLength(f),
                f.segments.size(), f.arcs.size());
  }
  std::printf("%-5s %6s | %7s %7s %6s %7s | %8s %6s | %8s %8s\n", "field", "points", "min ms",
              "med ms", "ok", "vs 100", "grid ms", "ok", "x min", "x med");
  std::map<std::pair<std::string, int>, Timing> all;
  for (const std::string& name : kFields) {
    // The grid search once per frame of 300 points (it takes 20-100 ms); every row's speed-up
    // is against it.
    const auto& grid_frames = frames(name, 300);
    int grid_ok = 0;
    double t_grid = 0.0;
    for (const Frame& frame : grid_frames) {
      const double t0 = cpuSeconds();
      const auto optima = gridSearch(name).locate(frame.ground);
      t_grid += cpuSeconds() - t0;
      for (const auto& o : optima) {
        if (correct(o.field_T_robot, frame.truth)) {
          ++grid_ok;
          break;
        }
      }
    }
    const double grid_ms = 1e3 * t_grid / grid_frames.size();
    for (int n : {100, 300, 1000}) {
      const Timing t = timeLocate(name, n, kRepetitions);
      all[{name, n}] = t;
      const double m = static_cast<double>(frames(name, n).size());
      const double growth = t.min_ms / std::max(all[{name, 100}].min_ms, 1e-9);
      std::printf("%-5s %6d | %7.3f %7.3f %5.0f%% %6.2fx | %8.1f %5.0f%% | %7.0fx %7.0fx\n",
                  name.c_str(), n, t.min_ms, t.median_ms, 100.0 * t.ok / m, growth, grid_ms,
                  100.0 * grid_ok / grid_frames.size(), grid_ms / std::max(t.min_ms, 1e-9),
                  grid_ms / std::max(t.median_ms, 1e-9));
    }
  }
  std::printf("map size, msl / spl (min ms):");
  for (int n : {100, 300, 1000}) {
    std::printf("  %d points %.2fx", n,
                all[{"msl", n}].min_ms / std::max(all[{"spl", n}].min_ms, 1e-9));
  }
  const std::size_t cap = localizer("spl").config().max_points;
  std::printf(
      "\n(inputs above max_points = %zu are subsampled evenly before step 1, so 1000 "
      "points cost about what %zu do)\n",
      cap, cap);
  const auto& fs = frames("spl", 300);
  double t_ours = 0.0, t_cv = 0.0;
  for (int rep = 0; rep < 20; ++rep) {
    for (const Frame& f : fs) {
      double t0 = cpuSeconds();
      const HoughTransform ht =
          localizer("spl").sensorTransform(localizer("spl").preparePoints(f.ground));
      t_ours += cpuSeconds() - t0;
      benchmark::DoNotOptimize(ht.column(0));
      std::vector<cv::Point2f> pts;
      double range = 0.03;
      for (const auto& p : f.ground.points) {
        pts.emplace_back(static_cast<float>(p.p_robot.x()), static_cast<float>(p.p_robot.y()));
        range = std::max(range, p.p_robot.norm());
      }
      t0 = cpuSeconds();
      cv::Mat lines;
      cv::HoughLinesPointSet(pts, lines, 20, 5, -range, range, 0.03, 0.0, CV_PI, CV_PI / 180.0);
      t_cv += cpuSeconds() - t0;
    }
  }
  std::printf(
      "step 1, 300 points: HoughTransform %.1f us, cv::HoughLinesPointSet %.1f us (%.1fx)\n",
      1e6 * t_ours / (20.0 * fs.size()), 1e6 * t_cv / (20.0 * fs.size()),
      t_cv / std::max(t_ours, 1e-12));
}

/// Frame `k` of the worst-frame set of a field (printWorstFrames).
SyntheticFrame worstFrame(const std::string& name, int k, std::mt19937_64& rng) {
  static const std::vector<std::string> views = {"nao-top", "nao-bottom", "kid-wide", "adult"};
  SyntheticConfig config;
  config.view = viewModel(views[k % views.size()]);
  config.seed = 7000 + k;
  config.occluders = k % 3 == 0 ? 1 : 0;
  return generateFrame(field(name), randomPose(field(name), 0.3, rng), config);
}

/// The worst frame: 500 random-pose frames per field preset, the four camera presets in turn
/// (every third frame with an occluding robot; parallel-only, one-direction and empty views
/// included). Each frame's CPU time is the median of 3 runs; the table gives median, p99 and
/// maximum, and the grid search's median time on every 25th frame with the speed-up beside each
/// figure. Success counts frames with two directions in view (DESIGN §5.3).
void printWorstFrames() {
  constexpr int kWorstFrames = 500, kRuns = 3, kGridEvery = 25;
  const std::vector<std::string> fields = {"spl", "spl2019", "kid", "adult", "msl"};
  const std::vector<std::string> views = {"nao-top", "nao-bottom", "kid-wide", "adult"};
  std::printf(
      "\nworst frame: %d random-pose frames per field, views %s/%s/%s/%s in turn, CPU ms per "
      "locate() (median of %d runs per frame); grid search on every %dth frame\n",
      kWorstFrames, views[0].c_str(), views[1].c_str(), views[2].c_str(), views[3].c_str(), kRuns,
      kGridEvery);
  std::printf("%-8s %5s %5s | %7s %7s %7s | %6s | %8s | %8s %8s %8s\n", "field", "2dir", "par",
              "med ms", "p99 ms", "max ms", "ok", "grid ms", "x med", "x p99", "x max");
  for (const std::string& name : fields) {
    std::mt19937_64 rng(3000);
    std::vector<double> ms, grid_ms;
    int two = 0, parallel = 0, ok = 0;
    for (int k = 0; k < kWorstFrames; ++k) {
      const SyntheticFrame f = worstFrame(name, k, rng);
      std::vector<double> runs;
      std::vector<PoseHypothesis> hs;
      for (int r = 0; r < kRuns; ++r) {
        const double t0 = cpuSeconds();
        hs = localizer(name).locate(f.ground);
        runs.push_back(1e3 * (cpuSeconds() - t0));
      }
      std::sort(runs.begin(), runs.end());
      ms.push_back(runs[runs.size() / 2]);
      parallel += hasOnlyParallelLines(f);
      if (hasTwoDirections(f)) {
        ++two;
        for (const auto& h : hs) {
          if (correct(h.field_T_robot, f.field_T_robot)) {
            ++ok;
            break;
          }
        }
      }
      if (k % kGridEvery != 0) continue;
      const double t0 = cpuSeconds();
      benchmark::DoNotOptimize(gridSearch(name).locate(f.ground).size());
      grid_ms.push_back(1e3 * (cpuSeconds() - t0));
    }
    std::sort(ms.begin(), ms.end());
    std::sort(grid_ms.begin(), grid_ms.end());
    const double med = ms[ms.size() / 2], p99 = ms[ms.size() * 99 / 100], worst = ms.back();
    const double grid = grid_ms[grid_ms.size() / 2];
    std::printf("%-8s %5d %5d | %7.3f %7.3f %7.3f | %5.1f%% | %8.1f | %7.0fx %7.0fx %7.0fx\n",
                name.c_str(), two, parallel, med, p99, worst, 100.0 * ok / std::max(two, 1), grid,
                grid / std::max(med, 1e-9), grid / std::max(p99, 1e-9),
                grid / std::max(worst, 1e-9));
  }
}

/// `--profile=FIELD/POINTS`: locate() once on each summary frame of that row; `--profile=
/// worst/FIELD`: once on each worst-frame frame of that field, printing the slowest ten
/// (`worst/FIELD/K`: frame K of them alone, as numbered in that list). No grid
/// search and no Google benchmark, so that an instruction count (callgrind with --toggle-collect
/// on locate) covers exactly these calls.
int profile(const std::string& what) {
  const std::size_t slash = what.find('/');
  if (slash == std::string::npos) return 1;
  const std::string a = what.substr(0, slash), b = what.substr(slash + 1);
  if (a != "worst") {
    for (const Frame& f : frames(a, std::stoi(b))) {
      benchmark::DoNotOptimize(localizer(a).locate(f.ground).size());
    }
    return 0;
  }
  // `worst/FIELD/K`: frame K alone (the frames are drawn in order, so it is the same frame).
  const std::size_t slash2 = b.find('/');
  const std::string name = b.substr(0, slash2);
  const int only = slash2 == std::string::npos ? -1 : std::stoi(b.substr(slash2 + 1));
  constexpr int kWorstFrames = 500;
  std::mt19937_64 rng(3000);
  const GlobalHoughLocalizer& ghl = localizer(name);  // the map part is built here, not timed
  std::vector<std::pair<double, int>> ms;
  std::vector<char> kind(kWorstFrames);
  for (int k = 0; k < kWorstFrames; ++k) {
    const SyntheticFrame f = worstFrame(name, k, rng);
    if (only >= 0 && k != only) continue;
    kind[k] = hasOnlyParallelLines(f) ? 'p' : hasTwoDirections(f) ? '2' : '-';
    const double t0 = cpuSeconds();
    benchmark::DoNotOptimize(ghl.locate(f.ground).size());
    ms.emplace_back(1e3 * (cpuSeconds() - t0), k);
  }
  std::sort(ms.rbegin(), ms.rend());
  for (int i = 0; i < std::min<int>(10, ms.size()); ++i) {
    std::printf("frame %3d (%c): %.3f ms\n", ms[i].second, kind[ms[i].second], ms[i].first);
  }
  return 0;
}

}  // namespace
}  // namespace houghloc

int main(int argc, char** argv) {
  // `--no_summary`: the Google benchmarks alone (for profiling one of them).
  bool summary = true;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) != "--no_summary") continue;
    summary = false;
    for (int j = i; j + 1 < argc; ++j) argv[j] = argv[j + 1];
    --argc;
    break;
  }
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--profile=", 0) == 0) return houghloc::profile(arg.substr(10));
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (!summary) return 0;
  houghloc::printSummary();
  houghloc::printWorstFrames();
  return 0;
}
