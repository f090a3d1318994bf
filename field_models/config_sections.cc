#include "field_models/config_sections.h"

namespace houghloc {

std::pair<std::string, ConfigField> configMember(const std::string& name, bool* value) {
  return {name,
          {[value](const cv::FileNode& node) {
             // OpenCV's YAML reader gives true/false as strings; the written form is 0/1.
             if (node.isString()) {
               const std::string text = node.string();
               if (text == "true" || text == "True" || text == "TRUE") {
                 *value = true;
               } else if (text == "false" || text == "False" || text == "FALSE") {
                 *value = false;
               } else {
                 throw std::invalid_argument("expected 0, 1, true or false");
               }
               return;
             }
             if (!node.isInt()) throw std::invalid_argument("expected 0, 1, true or false");
             const int number = static_cast<int>(node);
             if (number != 0 && number != 1) {
               throw std::invalid_argument("expected 0, 1, true or false");
             }
             *value = number != 0;
           },
           [value](cv::FileStorage& storage, const std::string& key) {
             storage << key << static_cast<int>(*value);
           }}};
}

void readConfigSection(const cv::FileNode& node, const ConfigSection& section,
                       const std::string& where) {
  if (node.empty() || node.isNone()) return;
  if (!node.isMap()) throw std::runtime_error(where + ": expected a map");
  for (cv::FileNodeIterator it = node.begin(); it != node.end(); ++it) {
    const cv::FileNode child = *it;
    const std::string key = child.name();
    const std::string path = where + "." + key;
    bool known = false;
    for (const auto& [name, sub] : section.children) {
      if (name != key) continue;
      readConfigSection(child, sub, path);
      known = true;
    }
    for (const auto& [name, field] : section.fields) {
      if (name != key) continue;
      known = true;
      if (child.isNone()) continue;  // `key:` without a value keeps the default
      try {
        field.read(child);
      } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
      }
    }
    if (!known) throw std::runtime_error(path + ": unknown key");
  }
}

void writeConfigSection(cv::FileStorage& storage, const std::string& name,
                        const ConfigSection& section) {
  storage << name << "{";
  for (const auto& [key, field] : section.fields) field.write(storage, key);
  for (const auto& [key, sub] : section.children) writeConfigSection(storage, key, sub);
  storage << "}";
}

}  // namespace houghloc
