#include "localization/localizer_config_io.h"

#include <gtest/gtest.h>

#include <string>

namespace houghloc {
namespace {

std::string written(const LocalizerConfig& config) {
  cv::FileStorage storage(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  writeLocalizerConfig(storage, config);
  return storage.releaseAndGetString();
}

LocalizerConfig readText(const std::string& text, const std::string& source = "cfg.yaml") {
  cv::FileStorage storage(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
  return readLocalizerConfig(storage.root(), source);
}

std::string errorOf(const std::string& body) {
  try {
    readText("%YAML:1.0\n---\n" + body);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

/// Copies a map tree, changing every number: integers v -> (v == 1 ? 0 : v + 1) (bools flip),
/// reals v -> 1.5 v + 0.001. Strings (enum names) stay.
void writePerturbed(cv::FileStorage& out, const cv::FileNode& node) {
  for (cv::FileNodeIterator it = node.begin(); it != node.end(); ++it) {
    const cv::FileNode child = *it;
    if (child.isMap()) {
      out << child.name() << "{";
      writePerturbed(out, child);
      out << "}";
    } else if (child.isInt()) {
      const int v = static_cast<int>(child);
      out << child.name() << (v == 1 ? 0 : v + 1);
    } else if (child.isReal()) {
      out << child.name() << 1.5 * static_cast<double>(child) + 0.001;
    } else {
      out << child.name() << static_cast<std::string>(child);
    }
  }
}

TEST(LocalizerConfigIo, ModifiedValuesRoundTrip) {
  LocalizerConfig config;
  config.global.max_points = 777;
  config.global.use_circle = false;
  config.global.map.hough.rho_step_m = 0.025;
  config.global.map.grid.margin_m = 0.7;
  config.global.hypotheses.temperature = 0.1234567890123;
  config.tracker.update.kernel = PointUpdateConfig::Kernel::kHuber;
  config.tracker.set.max_hypotheses = 5;
  config.tracker.motion.trans_var_per_m = 0.02;
  config.tracker.disagree_frames = 9;
  config.max_injected_hypotheses = 3;
  config.fallen_tilt_rad = 0.9;

  const std::string text = written(config);
  EXPECT_NE(text, written(LocalizerConfig{}));
  const LocalizerConfig back = readText(text);
  EXPECT_EQ(back.global.max_points, 777u);
  EXPECT_FALSE(back.global.use_circle);
  EXPECT_DOUBLE_EQ(back.global.map.hough.rho_step_m, 0.025);
  EXPECT_DOUBLE_EQ(back.global.map.grid.margin_m, 0.7);
  EXPECT_DOUBLE_EQ(back.global.hypotheses.temperature, 0.1234567890123);
  EXPECT_EQ(back.tracker.update.kernel, PointUpdateConfig::Kernel::kHuber);
  EXPECT_EQ(back.tracker.set.max_hypotheses, 5);
  EXPECT_DOUBLE_EQ(back.tracker.motion.trans_var_per_m, 0.02);
  EXPECT_EQ(back.tracker.disagree_frames, 9);
  EXPECT_EQ(back.max_injected_hypotheses, 3);
  EXPECT_DOUBLE_EQ(back.fallen_tilt_rad, 0.9);
  EXPECT_EQ(written(back), text);  // every other member too
}

TEST(LocalizerConfigIo, EveryKeyIsBoundToItsOwnMember) {
  // Every written number changed to a distinct new value must come back: a key bound to the
  // wrong member or not read at all would show up as a difference.
  cv::FileStorage defaults(written(LocalizerConfig{}),
                           cv::FileStorage::READ | cv::FileStorage::MEMORY);
  cv::FileStorage perturbed(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  writePerturbed(perturbed, defaults.root());
  const std::string text = perturbed.releaseAndGetString();
  const LocalizerConfig back = readText(text);
  EXPECT_EQ(written(back), text);
  EXPECT_EQ(back.global.max_points, LocalizerConfig{}.global.max_points + 1);
  EXPECT_GT(text.size(), 3000u);  // about 120 keys
}

TEST(LocalizerConfigIo, MissingSectionsKeepDefaultsAndOthersAreIgnored) {
  const LocalizerConfig config = readText(
      "%YAML:1.0\n---\nvision:\n  bogus: 1\nlcm:\n  url: x\ntracker:\n  injected_share: 0.3\n");
  EXPECT_DOUBLE_EQ(config.tracker.injected_share, 0.3);
  EXPECT_EQ(written(config).size(), written(LocalizerConfig{}).size());
}

TEST(LocalizerConfigIo, ErrorsNameFileAndKey) {
  EXPECT_EQ(errorOf("tracker:\n  motion:\n    bogus: 1\n"),
            "cfg.yaml: tracker.motion.bogus: unknown key");
  EXPECT_EQ(errorOf("global:\n  max_points: lots\n"),
            "cfg.yaml: global.max_points: expected a number");
  EXPECT_EQ(errorOf("global:\n  map:\n    hough:\n      rho_step_m: [1]\n"),
            "cfg.yaml: global.map.hough.rho_step_m: expected a number");
  EXPECT_EQ(errorOf("localizer:\n  max_injected_hypotheses: 2.5\n"),
            "cfg.yaml: localizer.max_injected_hypotheses: expected an integer");
  EXPECT_EQ(errorOf("tracker:\n  update:\n    kernel: tukey\n"),
            "cfg.yaml: tracker.update.kernel: expected one of huber, cauchy");
  EXPECT_EQ(errorOf("localizer: 3\n"), "cfg.yaml: localizer: expected a map");
}

}  // namespace
}  // namespace houghloc
