#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/tools/render/render_test_util.h"
#include "tools/recording/recording.h"
#include "tools/render/scenario.h"

namespace houghloc {
namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Every file of a folder, by relative path.
std::map<std::string, std::string> folderFiles(const std::string& folder) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(folder)) {
    if (e.is_regular_file()) files[fs::relative(e.path(), folder).string()] = contents(e.path());
  }
  return files;
}

RenderJob allOptionsJob(const std::string& folder, int frames) {
  RenderJob job = testJob("spl", "nao-top", folder);
  job.scenario = loadScenario(HOUGHLOC_SOURCE_DIR "/tools/render/scenarios/all_options.yaml");
  job.mount = *job.scenario.camera_mount;
  job.scenario.frames = frames;
  return job;
}

TEST(RenderDeterminismTest, SameSeedSameBytes) {
  RenderJob a = allOptionsJob("same_seed_a", 12), b = allOptionsJob("same_seed_b", 12);
  renderRecording(a);
  renderRecording(b);
  const auto fa = folderFiles(a.out_dir), fb = folderFiles(b.out_dir);
  ASSERT_EQ(fa.size(), fb.size());
  for (const auto& [name, data] : fa) {
    ASSERT_TRUE(fb.count(name)) << name;
    EXPECT_TRUE(data == fb.at(name)) << name << " differs";
  }
  RenderJob c = allOptionsJob("other_seed", 2);
  c.scenario.seed = 8;
  renderRecording(c);
  EXPECT_NE(contents(fs::path(c.out_dir) / "images/000001.jpg"), fa.at("images/000001.jpg"));
}

TEST(RenderDeterminismTest, AllOptionsScenarioRendersACompleteFolder) {
  RenderJob job = allOptionsJob("all_options", 60);
  renderRecording(job);
  const Recording rec = readRecording(job.out_dir);
  ASSERT_EQ(rec.frames.size(), 60u);
  EXPECT_EQ(rec.ground_truth.size(), 60u);
  ASSERT_TRUE(rec.field.has_value());
  EXPECT_EQ(rec.field->segments.size(), job.field.segments.size());
  EXPECT_EQ(rec.hints.size(), 3u);
  ASSERT_EQ(rec.events.size(), 4u);
  EXPECT_EQ(rec.events[0].event, "KIDNAP");
  EXPECT_EQ(rec.events[2].event, "FALL_START");
  EXPECT_EQ(rec.events[3].event, "FALL_END");
  EXPECT_FALSE(rec.visible.empty());
  // The recorded camera pose carries the configured bias (pitch -1 deg, noise 0.1 deg).
  const Pose3 recorded = rec.frames[0].robot_T_camera;
  EXPECT_NEAR(recorded.pitch - job.mount.pitch, -M_PI / 180.0, 0.01);
  // While lying on its back (FALL_START + 0.3 s .. FALL_END) the camera sees no lines.
  for (const VisibleRecord& v : rec.visible) {
    EXPECT_FALSE(v.t_us > rec.events[2].t_us + 300000 && v.t_us < rec.events[3].t_us - 150000)
        << v.feature << " visible at " << v.t_us;
  }
  for (const FrameRecord& f : rec.frames) {
    EXPECT_TRUE(fs::exists(fs::path(job.out_dir) / f.image)) << f.image;
  }
}

}  // namespace
}  // namespace houghloc
