#include "tools/offline/offline_config.h"

#include <filesystem>
#include <fstream>
#include <opencv2/core/persistence.hpp>
#include <sstream>
#include <stdexcept>

#include "field_models/yaml_precheck.h"
#include "localization/localizer_config_io.h"
#include "vision/vision_config_io.h"

namespace houghloc {

cv::FileStorage openConfigFile(const std::string& path) {
  if (!std::filesystem::exists(path)) {
    throw std::runtime_error(path + ": config file does not exist");
  }
  std::ifstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot read the config file");
  std::stringstream text;
  text << file.rdbuf();
  std::string yaml = text.str();
  checkYamlBeforeFileStorage(yaml, path);  // FileStorage hangs on some malformed YAML
  // OpenCV's reader wants the "%YAML:1.0" line that --print-config writes; a hand-written file
  // without it is accepted too.
  if (yaml.rfind("%YAML", 0) != 0) yaml = "%YAML:1.0\n---\n" + yaml;
  cv::FileStorage storage;
  try {
    storage.open(yaml,
                 cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  } catch (const cv::Exception& e) {
    throw std::runtime_error(path + ": not a valid YAML config: " + e.err);
  }
  if (!storage.isOpened()) throw std::runtime_error(path + ": cannot be read as YAML");
  return storage;
}

OfflineConfig loadOfflineConfig(const std::string& path) {
  OfflineConfig config;
  if (path.empty()) return config;
  const cv::FileStorage storage = openConfigFile(path);
  // Other sections (a node's `node:`, say) belong to other tools and are left alone.
  const cv::FileNode root = storage.root();
  config.vision = readVisionConfig(root["vision"], path);
  config.localizer = readLocalizerConfig(root, path);
  return config;
}

std::string defaultConfigYaml() {
  cv::FileStorage storage(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  writeVisionConfig(storage, VisionConfig{});
  writeLocalizerConfig(storage, LocalizerConfig{});
  return storage.releaseAndGetString();
}

}  // namespace houghloc
