#include "tools/realframes/real_summary.h"

#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

namespace houghloc {
namespace {

namespace fs = std::filesystem;

void count(const RealFrameLabel& label, int points, DetectorCounts* c) {
  c->points += points;
  if (label.lines_visible == "yes" && points == 0) ++c->yes_empty;
  if (label.lines_visible == "no") {
    c->no_points += points;
    if (points > 0) ++c->no_frames_with_points;
  }
}

}  // namespace

RealFolderSummary summarizeRealFolder(const std::string& data_dir, const std::string& folder,
                                      const std::vector<RealFrameOutcome>& outcomes) {
  RealFolderSummary s;
  s.folder = folder;
  for (const RealFrameOutcome& o : outcomes) {
    ++s.frames;
    const std::string& lines = o.label.lines_visible;
    s.yes += lines == "yes";
    s.faint += lines == "faint";
    s.no += lines == "no";
    count(o.label, o.points, &s.houghloc);
    count(o.label, o.baseline_points, &s.baseline);
    if (lines == "yes" && o.points == 0) {
      const FieldColor& c = o.diagnostics.field_color;
      char colour[96];
      std::snprintf(colour, sizeof colour,
                    " (field r %.2f g %.2f radius %.2f share %.2f texture sigma %.0f)", c.r, c.g,
                    c.radius, c.field_share, c.texture_sigma);
      s.yes_empty_images.push_back(o.label.image + ": " + frameRejectionName(o.rejection) + colour);
    }
    if (lines == "no" && o.points > 0)
      s.no_images_with_points.emplace_back(o.label.image, o.points);
    if (!o.label.has_mask) continue;
    const fs::path mask =
        fs::path(data_dir) / folder / "labels" / (fs::path(o.label.image).stem().string() + ".png");
    const cv::Mat labels = cv::imread(mask.string(), cv::IMREAD_GRAYSCALE);
    if (labels.empty()) continue;
    s.mask = maskMetrics(labels, o.point_pixels);
    s.baseline_mask = maskMetrics(labels, o.baseline_pixels);
  }
  return s;
}

void printRealSummaryHeader() {
  std::printf("%-26s %6s %11s | %9s %8s %9s | %9s %8s %9s\n", "folder", "frames", "yes/fnt/no",
              "yes-empty", "pts/frm", "no-pts", "base-empty", "base-pts", "base-no");
}

void printRealSummary(const RealFolderSummary& s) {
  const double n = s.frames > 0 ? s.frames : 1;
  std::printf("%-26s %6d %4d/%2d/%3d | %9d %8.1f %9ld | %9d %8.1f %9ld\n", s.folder.c_str(),
              s.frames, s.yes, s.faint, s.no, s.houghloc.yes_empty, s.houghloc.points / n,
              s.houghloc.no_points, s.baseline.yes_empty, s.baseline.points / n,
              s.baseline.no_points);
  if (s.mask) {
    std::printf(
        "  mask: houghloc %d points, precision %.2f, recall %.2f (%d off-line on field) | "
        "baseline %d points, precision %.2f, recall %.2f\n",
        s.mask->points, s.mask->precision, s.mask->recall, s.mask->off_line_on_field,
        s.baseline_mask->points, s.baseline_mask->precision, s.baseline_mask->recall);
  }
  for (const std::string& image : s.yes_empty_images) std::printf("  empty: %s\n", image.c_str());
}

}  // namespace houghloc
