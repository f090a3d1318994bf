// houghloc-frame-stats: turf, line, background, noise, blur and vignetting statistics of recorded
// folders (real or rendered), one table row per folder, to compare renders with real frames.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "tools/realframes/frame_statistics.h"

namespace {

namespace fs = std::filesystem;

/// A recorded folder itself, or the recorded folders directly inside a tree (the real set).
std::vector<std::string> recordedFolders(const std::string& path) {
  if (fs::exists(fs::path(path) / "frames.csv")) return {path};
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(path)) {
    if (entry.is_directory() && fs::exists(entry.path() / "frames.csv"))
      out.push_back(entry.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string number(double v, const char* format) {
  if (std::isnan(v)) return "-";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

void printRow(const houghloc::FolderStatistics& f) {
  const houghloc::FrameStatistics& m = f.median;
  std::printf(
      "| %s | %d | %s±%s | %s±%s | %s±%s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s %s |\n",
      fs::path(f.folder).filename().c_str(), f.frames, number(m.turf_r, "%.3f").c_str(),
      number(m.turf_r_spread, "%.3f").c_str(), number(m.turf_g, "%.3f").c_str(),
      number(m.turf_g_spread, "%.3f").c_str(), number(m.turf_luma, "%.0f").c_str(),
      number(m.turf_luma_spread, "%.1f").c_str(), number(m.turf_share, "%.2f").c_str(),
      number(m.background_share, "%.2f").c_str(), number(m.line_contrast, "%.0f").c_str(),
      number(m.line_g, "%.3f").c_str(),
      (std::to_string(f.frames_with_lines) + (f.masked_frames ? " (mask)" : "")).c_str(),
      number(m.edge_width_px, "%.1f").c_str(), number(m.noise_sigma, "%.1f").c_str(),
      number(m.vignetting_ratio, "%.2f").c_str(), number(m.image_luma, "%.0f").c_str(),
      number(m.image_r, "%.3f").c_str(), number(m.image_g, "%.3f").c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Colour and sensor statistics of recorded folders (real or rendered), one markdown table "
      "row per folder, medians over its frames: turf chromaticity r, g and luma with their "
      "robust spread (turf = pixels below the horizon near the sample's median colour), the "
      "share of the image that is turf-coloured and above the horizon, line contrast and "
      "chromaticity g (label masks where labels/<stem>.png exists, else bright near-grey pixels "
      "below the horizon), frames with lines, edge width of the lines, high-pass noise sigma on "
      "flat turf, turf luma of the outer ring over the centre (vignetting), image luma and mean "
      "chromaticity r g. A tree of recorded folders (e.g. ../shared/data/real) gives a row for "
      "each."};
  std::vector<std::string> paths;
  int max_frames = 0;
  app.add_option("folders", paths, "recorded folders, or folders holding recorded folders")
      ->required()
      ->check(CLI::ExistingDirectory);
  app.add_option("--max-frames", max_frames, "frames per folder, evenly spread (0: all)")
      ->check(CLI::NonNegativeNumber);
  CLI11_PARSE(app, argc, argv);
  std::printf(
      "| folder | frames | turf r | turf g | turf Y | turf share | above horizon | line dY | "
      "line g | frames with lines | edge px | noise | vignetting | image Y | image r g |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  try {
    for (const std::string& path : paths) {
      const std::vector<std::string> folders = recordedFolders(path);
      if (folders.empty()) {
        std::fprintf(stderr, "houghloc-frame-stats: %s: no frames.csv in it or below\n",
                     path.c_str());
        return 2;
      }
      for (const std::string& folder : folders) {
        printRow(houghloc::measureFolder(folder, max_frames));
        std::fflush(stdout);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "houghloc-frame-stats: %s\n", e.what());
    return 1;
  }
  return 0;
}
