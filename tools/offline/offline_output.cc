#include "tools/offline/offline_output.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

namespace houghloc {

namespace fs = std::filesystem;

void writeMetricsSection(const std::string& out_dir, const std::string& section,
                         const nlohmann::json& value) {
  const std::string path = (fs::path(out_dir) / "metrics.json").string();
  nlohmann::json all = nlohmann::json::object();
  if (std::ifstream in(path); in) {
    try {
      in >> all;
    } catch (const nlohmann::json::exception&) {
      all = nlohmann::json::object();  // a broken earlier file is replaced, not merged
    }
    if (!all.is_object()) all = nlohmann::json::object();
  }
  all[section] = value;
  std::ofstream out(path);
  out << all.dump(2) << "\n";
  if (!out) throw std::runtime_error(path + ": cannot write");
}

std::optional<cv::Mat> loadFrameImage(const OfflineContext& context, const FrameRecord& frame,
                                      std::string* problem) {
  const fs::path path = fs::path(context.recording.folder) / frame.image;
  if (!fs::exists(path)) {
    *problem = path.string() + ": image missing, frame skipped";
    return std::nullopt;
  }
  cv::Mat image = cv::imread(path.string(), cv::IMREAD_COLOR);
  if (image.empty()) {
    *problem = path.string() + ": image unreadable, frame skipped";
    return std::nullopt;
  }
  return image;
}

void reportProgress(const OfflineContext& context, const char* what, int done, int total,
                    int every) {
  if (context.options.quiet) return;
  if (done % every != 0 && done != total) return;
  std::fprintf(stderr, "\r%s: frame %d/%d", what, done, total);
  if (done == total) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

}  // namespace houghloc
