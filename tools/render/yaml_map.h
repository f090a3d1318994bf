#pragma once

#include <opencv2/core/persistence.hpp>
#include <set>
#include <string>

namespace houghloc {

/// Strict reader for one YAML mapping of a cv::FileStorage: reads the keys it is asked for,
/// checks their types, and (finish()) rejects every key nobody asked for, so a typo in a scenario
/// is an error naming the key instead of a silently ignored option.
class YamlMap {
 public:
  /// `where` names the file, `path` the mapping inside it ("" for the top level).
  YamlMap(const cv::FileNode& node, std::string where, std::string path);

  bool has(const char* key) const;
  void read(const char* key, double& value);
  void read(const char* key, int& value);
  void read(const char* key, bool& value);
  void read(const char* key, std::string& value);
  /// The node of `key` (none when absent), marking the key as known.
  cv::FileNode child(const char* key);
  /// "file: path.key" for messages.
  std::string name(const std::string& key) const;
  /// Throws naming the first key that was never read.
  void finish() const;

  const std::string& where() const { return where_; }
  std::string childPath(const std::string& key) const;

 private:
  cv::FileNode node_;
  std::string where_;
  std::string path_;
  std::set<std::string> known_;
};

/// Number of a scalar node; throws with `name` when it is not a number.
double yamlNumber(const cv::FileNode& node, const std::string& name);

}  // namespace houghloc
