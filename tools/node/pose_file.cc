#include "tools/node/pose_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <sstream>
#include <stdexcept>

#include "field_models/yaml_precheck.h"

namespace houghloc {

void savePoseFile(const std::string& path, const GaussianPose& pose) {
  cv::FileStorage storage(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  storage << "x" << pose.mean.x << "y" << pose.mean.y << "theta" << pose.mean.theta;
  storage << "covariance"
          << "[";
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) storage << pose.covariance(r, c);
  storage << "]";
  const std::string text = storage.releaseAndGetString();
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error(tmp + ": cannot write the pose");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw std::runtime_error(path + ": cannot rename " + tmp + " to it");
}

std::optional<GaussianPose> loadPoseFile(const std::string& path) {
  if (!std::filesystem::exists(path)) return std::nullopt;
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  std::string yaml = text.str();
  if (yaml.rfind("%YAML", 0) != 0) yaml = "%YAML:1.0\n---\n" + yaml;  // a hand-written file
  checkYamlBeforeFileStorage(yaml, path);  // text that makes FileStorage hang or crash
  cv::FileStorage storage;
  try {
    storage.open(yaml,
                 cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  } catch (const cv::Exception& e) {
    throw std::runtime_error(path + ": not a saved pose: " + e.err);
  }
  if (!storage.isOpened()) throw std::runtime_error(path + ": cannot be read as YAML");
  auto number = [&](const cv::FileNode& node, const std::string& key) {
    if (!node.isReal() && !node.isInt()) throw std::runtime_error(path + ": " + key + ": missing");
    return static_cast<double>(node);
  };
  GaussianPose pose;
  pose.mean = Pose2(number(storage["x"], "x"), number(storage["y"], "y"),
                    number(storage["theta"], "theta"));
  const cv::FileNode covariance = storage["covariance"];
  if (!covariance.isSeq() || covariance.size() != 9)
    throw std::runtime_error(path + ": covariance: expected 9 numbers");
  for (int i = 0; i < 9; ++i) pose.covariance(i / 3, i % 3) = number(covariance[i], "covariance");
  if (!pose.isFinite()) throw std::runtime_error(path + ": the pose is not finite");
  return pose;
}

}  // namespace houghloc
