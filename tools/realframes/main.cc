// houghloc-real-report: runs the vision on the real robot frames (a folder tree with index.csv,
// such as ../shared/data/real) and prints per folder the frames with lines but no point, points
// per frame and the line-mask agreement, beside the naive column-scan baseline.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <set>

#include "tools/offline/offline_config.h"
#include "tools/realframes/groundtruth_report.h"
#include "tools/realframes/real_summary.h"
#include "tools/recording/recording.h"

int main(int argc, char** argv) {
  using namespace houghloc;
  CLI::App app{
      "Vision on the real frames: per folder, frames showing lines without a point (yes-empty), "
      "points per frame and points on no-line frames, houghloc beside the naive column scan "
      "(tools/baselines/column_scan.h); line-mask precision/recall on masked images."};
  std::string data_dir;
  std::vector<std::string> only;
  app.add_option("data", data_dir, "real-frame tree with index.csv (e.g. ../shared/data/real)")
      ->required();
  std::string config_file;
  app.add_option("--folder", only, "run only these folders (repeatable)");
  app.add_option("--config", config_file, "config YAML (its vision: section), as houghloc-offline");
  std::string overlay_dir;
  app.add_option("--coverage-overlay", overlay_dir,
                 "write each ground-truth frame of the --learn-tilt-first runs with the map's "
                 "visible line samples (green: a point within 0.15 m, red: none) and the points "
                 "(blue crosses) to DIR/<run>/<folder>_<image>.png");
  CLI11_PARSE(app, argc, argv);
  try {
    if (!std::filesystem::is_directory(data_dir)) {
      std::fprintf(stderr, "houghloc-real-report: %s: not a folder\n", data_dir.c_str());
      return 2;
    }
    const OfflineConfig offline_config = loadOfflineConfig(config_file);
    const VisionConfig& config = offline_config.vision;
    const std::vector<RealFrameLabel> labels = readRealIndex(data_dir);
    std::vector<std::string> folders;
    for (const RealFrameLabel& l : labels) {
      if (folders.empty() || folders.back() != l.folder) folders.push_back(l.folder);
    }
    const std::set<std::string> wanted(only.begin(), only.end());
    printRealSummaryHeader();
    int yes = 0, empty = 0, base_empty = 0;
    long no_points = 0;
    std::vector<GroundTruthFrameReport> truth_frames;  // folders with groundtruth.csv
    std::vector<std::string> truth_folders;
    for (const std::string& folder : folders) {
      if (!wanted.empty() && !wanted.count(folder)) continue;
      std::fprintf(stderr, "houghloc-real-report: %s\n", folder.c_str());
      const std::vector<RealFrameOutcome> outcomes =
          runRealFolder(data_dir, labels, folder, config);
      const RealFolderSummary s = summarizeRealFolder(data_dir, folder, outcomes);
      for (GroundTruthFrameReport& r : groundTruthFrames(data_dir, folder, outcomes)) {
        truth_frames.push_back(std::move(r));
      }
      if (folderHasGroundTruth(data_dir, folder)) truth_folders.push_back(folder);
      printRealSummary(s);
      yes += s.yes, empty += s.houghloc.yes_empty, base_empty += s.baseline.yes_empty;
      no_points += s.houghloc.no_points;
    }
    std::printf(
        "total: %d of %d yes-frames without a point (baseline %d); %ld points on no-frames\n",
        empty, yes, base_empty, no_points);
    if (!truth_folders.empty()) printGroundTruthFrames(truth_frames);
    const PipelineConfig pipeline_config{offline_config.vision, offline_config.localizer};
    for (const std::string& folder : truth_folders) {
      std::fprintf(stderr, "houghloc-real-report: %s --global-only\n", folder.c_str());
      printGlobalCheck((folder + ", recorded camera pose").c_str(),
                       globalCheckAtGroundTruth(data_dir, folder, pipeline_config));
      GlobalCheckConfig learn_first;
      learn_first.learn_tilt_first = true;
      if (!overlay_dir.empty()) learn_first.overlay_dir = overlay_dir + "/learn-tilt-first";
      printGlobalCheck((folder + ", recorded camera pose, --learn-tilt-first").c_str(),
                       globalCheckAtGroundTruth(data_dir, folder, pipeline_config, learn_first));
      if (!folderHasFitDpitch(data_dir, folder)) continue;
      GlobalCheckConfig with_fit;
      with_fit.add_fit_dpitch = true;
      printGlobalCheck((folder + ", camera pitch + fit_dpitch").c_str(),
                       globalCheckAtGroundTruth(data_dir, folder, pipeline_config, with_fit));
    }
    // One robot's cameras together, one pitch/roll corrector for both (its error lies in the
    // body or the head, which the cameras share), the tilt learned over all their frames first.
    PipelineConfig shared = pipeline_config;
    shared.vision.pose_correction.shared_between_cameras = true;
    GlobalCheckConfig learn_first;
    learn_first.learn_tilt_first = true;
    if (!overlay_dir.empty()) learn_first.overlay_dir = overlay_dir + "/shared-corrector";
    for (const std::vector<std::string>& cameras : sameRobotFolders(data_dir, truth_folders)) {
      std::string names;
      for (const std::string& c : cameras) names += (names.empty() ? "" : " + ") + c;
      std::fprintf(stderr, "houghloc-real-report: %s --global-only\n", names.c_str());
      printGlobalCheck((names + " as one robot's cameras, shared_between_cameras: 1, recorded "
                                "camera pose, --learn-tilt-first")
                           .c_str(),
                       globalCheckAtGroundTruth(data_dir, cameras, shared, learn_first));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "houghloc-real-report: %s\n", e.what());
    return 1;
  }
  return 0;
}
