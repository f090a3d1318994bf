// The vision on the real robot frames of ../shared/data/real (never copied into the repository):
// frames showing lines must give points, frames showing none few; line-mask agreement. Each
// figure is printed beside the naive column-scan baseline's.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

#include "tests/real/real_data.h"
#include "tools/realframes/real_summary.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

class RealFramesTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!fs::exists(fs::path(HOUGHLOC_REAL_DATA) / "index.csv")) return;
    const std::vector<RealFrameLabel> labels = readRealIndex(HOUGHLOC_REAL_DATA);
    std::vector<std::string> folders;
    for (const RealFrameLabel& l : labels) {
      if (folders.empty() || folders.back() != l.folder) folders.push_back(l.folder);
    }
    printRealSummaryHeader();
    for (const std::string& folder : folders) {
      summaries_[folder] = summarizeRealFolder(HOUGHLOC_REAL_DATA, folder,
                                               runRealFolder(HOUGHLOC_REAL_DATA, labels, folder));
      printRealSummary(summaries_[folder]);
    }
  }
  static std::map<std::string, RealFolderSummary> summaries_;
};

std::map<std::string, RealFolderSummary> RealFramesTest::summaries_;

TEST_F(RealFramesTest, FramesShowingLinesGivePoints) {
  REQUIRE_REAL_DATA();
  // Frames left without points (at most 7), with the stage that rejects them. Not yet
  // supported: grey carpets (the field model is green to teal turf).
  const std::set<std::string> unsupported = {
      // no field colour (grey carpet)
      "scarrix_nao_unknown/images/oisin_compete0138.png",
      "scarrix_nao_unknown/images/oisin_compete0158.png",
      "scarrix_nao_unknown/images/oisin_compete0214.png",
      "scarrix_nao_unknown/images/oisin_compete0276.png",
      // candidates not turf-bounded (before the continuation test its one point lay on a foot)
      "scarrix_nao_lower_320x240/images/lower_936261.jpg",
  };
  ASSERT_LE(unsupported.size(), 7u);
  int yes = 0, empty = 0;
  for (const auto& [folder, s] : summaries_) {
    yes += s.yes;
    for (const std::string& entry : s.yes_empty_images) {
      const std::string image = folder + "/" + entry.substr(0, entry.find(':'));
      ++empty;
      EXPECT_TRUE(unsupported.count(image)) << image << " shows lines but gave no point ("
                                            << entry.substr(entry.find(':') + 2) << ")";
    }
  }
  std::printf("yes-frames without a point: %d of %d\n", empty, yes);
  EXPECT_EQ(yes, 108);
}

TEST_F(RealFramesTest, FramesShowingNoLineGiveFewPoints) {
  REQUIRE_REAL_DATA();
  // Labelled "no" in index.csv but showing lines: the goal line and the goal area's line run
  // under the goal at the top left (the first scan's horizon is below them; the field seen above
  // it gives the pitch, field_top_pitch.h). 40 of its 57 points lay on them, 17 on the legs of a
  // robot standing at the far border (overlay checked; 17 of 17 on the lines before the lines'
  // widths refined the field top's pitch); 51 points since the scan reaches a pitch margin beyond
  // its range (ScanGridConfig::range_pitch_margin_rad), on the same lines and legs.
  const std::set<std::string> showing_lines = {"scarrix_nao_unknown/images/max_japan0127.png"};
  long points = 0, on_unlabelled_lines = 0;
  for (const auto& [folder, s] : summaries_) {
    for (const auto& [image, n] : s.no_images_with_points) {
      const bool lines = showing_lines.count(folder + "/" + image) > 0;
      (lines ? on_unlabelled_lines : points) += n;
      std::printf("no-line frame with points: %s/%s: %d%s\n", folder.c_str(), image.c_str(), n,
                  lines ? " (shows lines)" : "");
    }
  }
  std::printf("points on the 33 no-line frames: %ld, %ld more on lines the index misses\n", points,
              on_unlabelled_lines);
  // The target: at most 10. Measured 10: 6 on scarrix_nao_lower's robots (a fallen
  // robot's arm, bottom camera, 0.5-0.7 m ahead; 5 on danu_fallen_robot_5867, 1 on
  // max_ball_bottom0309), 3 on scarrix_nao_lower_320x240 (45 before the continuation test, 25
  // before the ball test, 20 before the support test), 1 on physar_nao_bottom
  // black1_point5_bottom, a speck of sunlit turf beside a shadow (since the turf's light levels
  // each have their threshold, FieldColor::lit_split).
  EXPECT_LE(points, 10);
}

TEST_F(RealFramesTest, MaskedImages) {
  REQUIRE_REAL_DATA();
  const std::map<std::string, std::pair<double, double>> floors = {
      // folder: (precision, recall) floors
      // its centre circle and halfway line lie above the nominal horizon; the first scan finds
      // specks of turf only, the field top rescan (step 4e) the lines, whose widths then give
      // the rest of the pitch (0.97 / 0.12 with the bound's pitch alone; 0.92 / 0.91 measured)
      {"bitbots_nao_upper", {0.9, 0.85}},
      // the recall target, 0.7, met since runs from dark pixels end at the turf (0.44 /
      // 0.63 before); its mask labels only fragments of the lines, so precision is low
      {"bitbots_kid_620x480", {0.4, 0.7}},  // 0.41 / 0.71 measured
      // far lines 1-3 px wide that take the turf's chroma are white by the light they add
      // (LineSpotConfig::max_blend_width_px; 0.79 / 0.38 by the peak's colour alone); the far
      // turf's own texture sets their threshold (LineSpotConfig::far_turf_m_per_px; 0.84 / 0.40
      // with the whole turf's, whose near texture and far-to-near gradient gave 44 grey levels
      // against the far halfway line's 38-43 at column 100)
      {"torso21_kid_800x600", {0.9, 0.55}},  // 0.92 / 0.58 measured
      // hard sunlight: 1 of its 13 points lies on a line (0.08 / 0.04 measured with 12 points
      // before the thin lines' added light; the new point lies in the sun, off the line)
      {"torso21_kid_620x480", {0.07, 0.03}},
  };
  for (const auto& [folder, floor] : floors) {
    const RealFolderSummary& s = summaries_.at(folder);
    ASSERT_TRUE(s.mask.has_value()) << folder;
    EXPECT_GE(s.mask->precision, floor.first) << folder;
    EXPECT_GE(s.mask->recall, floor.second) << folder;
  }
}

}  // namespace
}  // namespace houghloc
