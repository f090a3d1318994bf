#include "tools/render/yaml_map.h"

#include <cmath>
#include <stdexcept>

namespace houghloc {

YamlMap::YamlMap(const cv::FileNode& node, std::string where, std::string path)
    : node_(node), where_(std::move(where)), path_(std::move(path)) {
  if (!node_.isMap()) {
    throw std::runtime_error(where_ + ": " + (path_.empty() ? "top level" : path_) +
                             ": expected a mapping of keys");
  }
}

std::string YamlMap::childPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

std::string YamlMap::name(const std::string& key) const { return where_ + ": " + childPath(key); }

bool YamlMap::has(const char* key) const { return !node_[key].empty(); }

cv::FileNode YamlMap::child(const char* key) {
  known_.insert(key);
  return node_[key];
}

double yamlNumber(const cv::FileNode& node, const std::string& name) {
  if (!node.isReal() && !node.isInt()) throw std::runtime_error(name + ": expected a number");
  const double value = static_cast<double>(node);
  if (!std::isfinite(value)) throw std::runtime_error(name + ": not a finite number");
  return value;
}

void YamlMap::read(const char* key, double& value) {
  const cv::FileNode n = child(key);
  if (!n.empty()) value = yamlNumber(n, name(key));
}

void YamlMap::read(const char* key, int& value) {
  const cv::FileNode n = child(key);
  if (n.empty()) return;
  if (!n.isInt()) throw std::runtime_error(name(key) + ": expected an integer");
  value = static_cast<int>(n);
}

void YamlMap::read(const char* key, bool& value) {
  const cv::FileNode n = child(key);
  if (n.empty()) return;
  if (n.isInt() && (static_cast<int>(n) == 0 || static_cast<int>(n) == 1)) {
    value = static_cast<int>(n) == 1;
    return;
  }
  if (n.isString()) {
    const std::string s = static_cast<std::string>(n);
    if (s == "true" || s == "yes" || s == "on") {
      value = true;
      return;
    }
    if (s == "false" || s == "no" || s == "off") {
      value = false;
      return;
    }
  }
  throw std::runtime_error(name(key) + ": expected true or false");
}

void YamlMap::read(const char* key, std::string& value) {
  const cv::FileNode n = child(key);
  if (n.empty()) return;
  if (!n.isString()) throw std::runtime_error(name(key) + ": expected a string");
  value = static_cast<std::string>(n);
}

void YamlMap::finish() const {
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string key = (*it).name();
    if (!known_.count(key)) throw std::runtime_error(name(key) + ": unknown key");
  }
}

}  // namespace houghloc
