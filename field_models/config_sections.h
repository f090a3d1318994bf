#pragma once

#include <functional>
#include <limits>
#include <opencv2/core/persistence.hpp>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace houghloc {

/// Reads and writes one member of a config struct. read() throws std::invalid_argument with a
/// short reason ("expected a number") that readConfigSection() prefixes with the key's path.
struct ConfigField {
  std::function<void(const cv::FileNode&)> read;
  std::function<void(cv::FileStorage&, const std::string& key)> write;
};

/// The keys of one config struct, in declaration order, and its nested structs as sub-maps.
/// A section binds members of a live object by pointer: build it, use it, drop it.
struct ConfigSection {
  using Fields = std::vector<std::pair<std::string, ConfigField>>;
  using Children = std::vector<std::pair<std::string, ConfigSection>>;

  ConfigSection() = default;
  ConfigSection(Fields fields_in, Children children_in = {})  // NOLINT: braced lists read well
      : fields(std::move(fields_in)), children(std::move(children_in)) {}

  Fields fields;
  Children children;
};

namespace config_detail {

template <typename T>
void readNumber(const cv::FileNode& node, T* value) {
  double number = 0.0;
  if (node.isInt()) {
    number = static_cast<int>(node);
  } else if (node.isReal()) {
    number = static_cast<double>(node);
  } else {
    throw std::invalid_argument("expected a number");
  }
  if constexpr (std::is_integral_v<T>) {
    if (number != static_cast<double>(static_cast<long long>(number))) {
      throw std::invalid_argument("expected an integer");
    }
    if (number < static_cast<double>(std::numeric_limits<T>::lowest()) ||
        number > static_cast<double>(std::numeric_limits<T>::max())) {
      throw std::invalid_argument("out of range");
    }
  }
  *value = static_cast<T>(number);
}

template <typename T>
void writeNumber(cv::FileStorage& storage, const std::string& key, T value) {
  if constexpr (std::is_integral_v<T>) {
    storage << key << static_cast<int>(value);
  } else {
    storage << key << static_cast<double>(value);
  }
}

}  // namespace config_detail

/// Binds a number member (int, std::size_t, double, float, ...). Integers reject fractions and
/// values out of the type's range (a negative count, say).
template <typename T>
std::pair<std::string, ConfigField> configMember(const std::string& name, T* value) {
  static_assert(std::is_arithmetic_v<T>, "configMember binds numbers, bools and enums");
  return {name,
          {[value](const cv::FileNode& node) { config_detail::readNumber(node, value); },
           [value](cv::FileStorage& storage, const std::string& key) {
             config_detail::writeNumber(storage, key, *value);
           }}};
}

/// Binds a bool member, written and read as 0 or 1 (OpenCV's YAML has no booleans).
std::pair<std::string, ConfigField> configMember(const std::string& name, bool* value);

/// Binds an enum member, written and read by name.
template <typename E>
std::pair<std::string, ConfigField> configEnumMember(const std::string& name, E* value,
                                                     std::vector<std::pair<std::string, E>> names) {
  return {name,
          {[value, names](const cv::FileNode& node) {
             std::string allowed;
             for (const auto& [text, option] : names) {
               if (node.isString() && static_cast<std::string>(node) == text) {
                 *value = option;
                 return;
               }
               allowed += (allowed.empty() ? "" : ", ") + text;
             }
             throw std::invalid_argument("expected one of " + allowed);
           },
           [value, names](cv::FileStorage& storage, const std::string& key) {
             for (const auto& [text, option] : names) {
               if (option == *value) storage << key << text;
             }
           }}};
}

/// Reads a map node into the bound members. A missing or empty node or key keeps the defaults.
/// Throws std::runtime_error "<where>.<key>: unknown key" / "<where>.<key>: expected ..." where
/// `where` names the source and the section (e.g. "config.yaml: vision").
void readConfigSection(const cv::FileNode& node, const ConfigSection& section,
                       const std::string& where);

/// Writes the bound members as the map `name`, nested structs as sub-maps.
void writeConfigSection(cv::FileStorage& storage, const std::string& name,
                        const ConfigSection& section);

}  // namespace houghloc
