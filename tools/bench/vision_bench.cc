// houghloc-bench-vision: the vision pipeline against a stock-OpenCV baseline on the same rendered
// frames, one core; prints the time ratio and both methods' precision/recall (issue 5). Then the
// pipeline on the frames as YUYV (read in place) against the same frames decoded to BGR8, and
// against converting each YUYV frame to BGR8 before running the pipeline.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "tools/offline/vision_metrics.h"
#include "tools/recording/recording.h"
#include "vision/image_conversion.h"
#include "vision/vision_pipeline.h"
#include "vision_baseline.h"

namespace {

using namespace houghloc;
namespace fs = std::filesystem;

struct BenchSet {
  std::string name;
  Recording recording;
  std::vector<cv::Mat> images;
};

/// Renders (once per build tree) and loads a recording.
BenchSet& benchSet(const std::string& name, const std::string& render_args) {
  static std::map<std::string, BenchSet> sets;
  auto it = sets.find(name);
  if (it != sets.end()) return it->second;
  const fs::path folder = fs::path(HOUGHLOC_BENCH_DIR) / name;
  if (!fs::exists(folder / ".complete")) {
    const std::string command = std::string(HOUGHLOC_RENDER_EXE) + " " + render_args +
                                " --frames 30 -q -o " + folder.string();
    if (std::system(command.c_str()) != 0) {
      std::fprintf(stderr, "bench: rendering failed: %s\n", command.c_str());
      std::exit(1);
    }
    std::ofstream(folder / ".complete");
  }
  BenchSet set;
  set.name = name;
  set.recording = readRecording(folder.string());
  for (const FrameRecord& frame : set.recording.frames) {
    set.images.push_back(cv::imread((folder / frame.image).string(), cv::IMREAD_COLOR));
  }
  return sets.emplace(name, std::move(set)).first->second;
}

BenchSet& vga() {
  return benchSet("vga_nao-top", "--standard spl --camera nao-top --trajectory walk --seed 201");
}
BenchSet& hd() {
  return benchSet("hd_adult", "--standard adult --camera adult --trajectory walk --seed 202");
}

VisionConfig configFor(const BenchSet& set) {
  VisionConfig config;
  config.line_width_m = set.recording.field->line_width;
  return config;
}

template <typename Method>
void runFrames(benchmark::State& state, BenchSet& set, Method&& method) {
  size_t i = 0;
  for (auto _ : state) {
    const FrameRecord& frame = set.recording.frames[i % set.images.size()];
    benchmark::DoNotOptimize(method(set.images[i % set.images.size()], frame.robot_T_camera));
    ++i;
  }
}

void BM_VisionPipeline(benchmark::State& state, BenchSet& (*get)()) {
  BenchSet& set = get();
  VisionPipeline pipeline(set.recording.intrinsicsFor(set.recording.frames[0]), configFor(set));
  runFrames(state, set, [&](const cv::Mat& image, const Pose3& pose) {
    return pipeline.process(image, pose).ground.size();
  });
}

/// The pipeline with one of its spot tests off (`off` turns it off in the config): what that
/// test costs, measured in the same run.
void BM_VisionPipelineWithout(benchmark::State& state, BenchSet& (*get)(),
                              void (*off)(VisionConfig*)) {
  BenchSet& set = get();
  VisionConfig config = configFor(set);
  off(&config);
  VisionPipeline pipeline(set.recording.intrinsicsFor(set.recording.frames[0]), config);
  runFrames(state, set, [&](const cv::Mat& image, const Pose3& pose) {
    return pipeline.process(image, pose).ground.size();
  });
}

void continuationOff(VisionConfig* config) { config->spots.continuation.enabled = false; }
void ballTestOff(VisionConfig* config) { config->spots.ball.enabled = false; }
void supportTestOff(VisionConfig* config) { config->spots.support.enabled = false; }

void BM_OpenCvBaseline(benchmark::State& state, BenchSet& (*get)()) {
  BenchSet& set = get();
  OpenCvLineBaseline baseline(set.recording.intrinsicsFor(set.recording.frames[0]));
  runFrames(state, set, [&](const cv::Mat& image, const Pose3& pose) {
    return baseline.process(image, pose).size();
  });
}

/// The set's frames as a NAO camera delivers them (YUYV) and that YUYV decoded to BGR8, so both
/// formats hold the same pixels.
struct YuyvFrames {
  std::vector<cv::Mat> yuyv, bgr;
};

const YuyvFrames& yuyvFrames(const BenchSet& set) {
  static std::map<std::string, YuyvFrames> frames;
  auto it = frames.find(set.name);
  if (it != frames.end()) return it->second;
  YuyvFrames out;
  for (const cv::Mat& image : set.images) {
    out.yuyv.push_back(bgrToYuyv(image));
    out.bgr.push_back(yuyvToBgr(out.yuyv.back()));
  }
  return frames.emplace(set.name, std::move(out)).first->second;
}

/// The pipeline on the set's frames as given by image(frames, k).
template <typename Image>
void runYuyvFrames(benchmark::State& state, BenchSet& (*get)(), Image&& image) {
  BenchSet& set = get();
  const YuyvFrames& frames = yuyvFrames(set);
  VisionPipeline pipeline(set.recording.intrinsicsFor(set.recording.frames[0]), configFor(set));
  size_t i = 0;
  for (auto _ : state) {
    const size_t k = i++ % frames.yuyv.size();
    const Pose3& pose = set.recording.frames[k].robot_T_camera;
    benchmark::DoNotOptimize(pipeline.process(image(frames, k), pose).ground.size());
  }
}

/// YUYV read in place.
void BM_VisionYuyvInPlace(benchmark::State& state, BenchSet& (*get)()) {
  runYuyvFrames(state, get, [](const YuyvFrames& f, size_t k) { return f.yuyv[k]; });
}

/// The YUYV frame's BGR8 decode (made before timing).
void BM_VisionYuyvDecoded(benchmark::State& state, BenchSet& (*get)()) {
  runYuyvFrames(state, get, [](const YuyvFrames& f, size_t k) { return f.bgr[k]; });
}

/// The whole YUYV frame converted with toBgr (into a reused buffer), then the BGR8 pipeline.
void BM_VisionYuyvConvertFirst(benchmark::State& state, BenchSet& (*get)()) {
  cv::Mat buffer;
  runYuyvFrames(state, get,
                [&](const YuyvFrames& f, size_t k) { return toBgr(f.yuyv[k], buffer); });
}

BENCHMARK_CAPTURE(BM_VisionPipeline, 640x480, &vga)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionPipelineWithout, no_continuation_640x480, &vga, &continuationOff)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionPipelineWithout, no_ball_test_640x480, &vga, &ballTestOff)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionPipelineWithout, no_support_test_640x480, &vga, &supportTestOff)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OpenCvBaseline, 640x480, &vga)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionPipeline, 1280x720, &hd)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionPipelineWithout, no_continuation_1280x720, &hd, &continuationOff)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionPipelineWithout, no_ball_test_1280x720, &hd, &ballTestOff)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionPipelineWithout, no_support_test_1280x720, &hd, &supportTestOff)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OpenCvBaseline, 1280x720, &hd)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionYuyvInPlace, 640x480, &vga)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionYuyvDecoded, 640x480, &vga)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionYuyvConvertFirst, 640x480, &vga)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionYuyvInPlace, 1280x720, &hd)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionYuyvDecoded, 1280x720, &hd)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VisionYuyvConvertFirst, 1280x720, &hd)->Unit(benchmark::kMillisecond);

/// Keeps each run's time per iteration (ms) for the ratio table.
class CollectingReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      ms[run.benchmark_name()] = run.GetAdjustedRealTime();  // in the run's unit (ms)
      cpu_ms[run.benchmark_name()] = run.GetAdjustedCPUTime();
    }
  }
  std::map<std::string, double> ms, cpu_ms;
};

VisionMetrics quality(BenchSet& set, bool baseline) {
  VisionPipeline pipeline(set.recording.intrinsicsFor(set.recording.frames[0]), configFor(set));
  OpenCvLineBaseline opencv(set.recording.intrinsicsFor(set.recording.frames[0]));
  VisionMetricsAccumulator metrics(*set.recording.field);
  for (size_t i = 0; i < set.images.size(); ++i) {
    const FrameRecord& frame = set.recording.frames[i];
    const GroundPoints points = baseline
                                    ? opencv.process(set.images[i], frame.robot_T_camera)
                                    : pipeline.process(set.images[i], frame.robot_T_camera).ground;
    const auto truth = groundTruthAt(set.recording.ground_truth, frame.t_us);
    if (!truth) continue;
    const CameraModel camera(set.recording.intrinsicsFor(frame), frame.robot_T_camera);
    metrics.addFrame(points, *truth, visibleAt(set.recording.visible, frame.t_us), camera);
  }
  return metrics.result();
}

/// CPU time per frame of the three YUYV paths and the ratios to reading YUYV in place (> 1: in
/// place is faster). CPU rather than wall time: on a shared machine the wall time also counts
/// the time other processes hold the core. Run with --benchmark_repetitions=N
/// --benchmark_enable_random_interleaving=true so load changes hit the three paths alike.
void printYuyvTable(const std::map<std::string, double>& ms) {
  std::printf("\n%-10s %12s %14s %16s %14s %16s\n", "frames", "YUYV ms", "BGR8 ms",
              "convert+BGR ms", "BGR / YUYV", "convert / YUYV");
  for (const std::string size : {"640x480", "1280x720"}) {
    // With --benchmark_repetitions the median of the repetitions.
    const auto find = [&](const std::string& name) {
      const auto median = ms.find(name + "_median");
      return median != ms.end() ? median : ms.find(name);
    };
    const auto yuyv = find("BM_VisionYuyvInPlace/" + size);
    const auto bgr = find("BM_VisionYuyvDecoded/" + size);
    const auto convert = find("BM_VisionYuyvConvertFirst/" + size);
    if (yuyv == ms.end() || bgr == ms.end() || convert == ms.end()) continue;
    std::printf("%-10s %12.3f %14.3f %16.3f %14.3f %16.3f\n", size.c_str(), yuyv->second,
                bgr->second, convert->second, bgr->second / yuyv->second,
                convert->second / yuyv->second);
  }
}

}  // namespace

int main(int argc, char** argv) {
  cv::setNumThreads(1);  // one core, like the pipeline (DESIGN §8)
  benchmark::Initialize(&argc, argv);
  CollectingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\n%-10s %14s %14s %8s   %-28s %-28s\n", "frames", "houghloc ms", "opencv ms",
              "ratio", "houghloc prec / recall 0-2,2-3,3-4", "opencv prec / recall");
  for (const auto& [size, get] : {std::pair<std::string, BenchSet& (*)()>{"640x480", &vga},
                                  std::pair<std::string, BenchSet& (*)()>{"1280x720", &hd}}) {
    const auto ours = reporter.ms.find("BM_VisionPipeline/" + size);
    const auto theirs = reporter.ms.find("BM_OpenCvBaseline/" + size);
    if (ours == reporter.ms.end() || theirs == reporter.ms.end()) continue;
    BenchSet& set = get();
    const VisionMetrics a = quality(set, false), b = quality(set, true);
    const auto text = [](const VisionMetrics& m) {
      char buffer[64];
      std::snprintf(buffer, sizeof(buffer), "%.3f / %.2f %.2f %.2f", m.precision, m.bands[0].recall,
                    m.bands[1].recall, m.bands[2].recall);
      return std::string(buffer);
    };
    std::printf("%-10s %14.3f %14.3f %8.2f   %-28s %-28s\n", size.c_str(), ours->second,
                theirs->second, theirs->second / ours->second, text(a).c_str(), text(b).c_str());
  }
  printYuyvTable(reporter.cpu_ms);
  benchmark::Shutdown();
  return 0;
}
