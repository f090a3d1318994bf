#include "field_models/spl_import.h"

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

namespace houghloc {
namespace {

using Json = nlohmann::json;

/// One key of DESIGN §4's table: its valid range (m) and where it goes.
struct KeyRule {
  const char* key;
  double min_m;
  double max_m;
  double FieldDimensions::*member;
  bool optional;  ///< goalAreaLength/Width: both or neither
};

const std::vector<KeyRule> kFieldRules = {
    {"length", 3.0, 20.0, &FieldDimensions::length, false},
    {"width", 3.0, 20.0, &FieldDimensions::width, false},
    {"lineWidth", 0.05, 0.05, &FieldDimensions::line_width, false},
    {"penaltyMarkSize", 0.01, 5.0, &FieldDimensions::penalty_mark_size, false},
    {"goalAreaLength", 0.3, 10.0, &FieldDimensions::goal_area_length, true},
    {"goalAreaWidth", 1.0, 10.0, &FieldDimensions::goal_area_width, true},
    {"penaltyAreaLength", 0.3, 10.0, &FieldDimensions::penalty_area_length, false},
    {"penaltyAreaWidth", 1.0, 10.0, &FieldDimensions::penalty_area_width, false},
    {"penaltyMarkDistance", 0.3, 10.0, &FieldDimensions::penalty_mark_distance, false},
    {"centerCircleDiameter", 0.3, 10.0, &FieldDimensions::center_circle_diameter, false},
    {"borderStripWidth", 0.2, 2.0, &FieldDimensions::border_strip_width, false},
};

const std::vector<KeyRule> kGoalRules = {
    {"postDiameter", 0.01, 4.0, &FieldDimensions::goal_post_diameter, false},
    {"height", 0.3, 10.0, &FieldDimensions::goal_height, false},
    {"innerWidth", 0.3, 10.0, &FieldDimensions::goal_inner_width, false},
    {"depth", 0.3, 10.0, &FieldDimensions::goal_depth, false},
};

/// Names used by earlier rule books and team code, with the current name to suggest.
const std::map<std::string, std::string> kOutdatedNames = {
    {"penaltyCrossSize", "penaltyMarkSize"},
    {"penaltyCrossDistance", "penaltyMarkDistance"},
    {"penaltyMarkerSize", "penaltyMarkSize"},
    {"penaltyMarkerDistance", "penaltyMarkDistance"},
    {"goalBoxAreaLength", "goalAreaLength"},
    {"goalBoxAreaWidth", "goalAreaWidth"},
    {"goalBoxLength", "goalAreaLength"},
    {"goalBoxWidth", "goalAreaWidth"},
    {"centreCircleDiameter", "centerCircleDiameter"},
    {"goalPostDiameter", "postDiameter"},
    {"goalHeight", "height"},
    {"goalInnerWidth", "innerWidth"},
    {"goalDepth", "depth"},
};

std::string typeName(const Json& value) {
  return value.is_boolean()  ? "a bool"
         : value.is_null()   ? "null"
         : value.is_string() ? "a string"
         : value.is_object() ? "an object"
         : value.is_array()  ? "an array"
                             : "not a number";
}

std::string shortest(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

/// "line 3, column 7" for a byte offset (nlohmann reports 1-based offsets past the error).
std::string position(const std::string& text, std::size_t byte) {
  const std::size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
  int line = 1, column = 1;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

/// Parses the text and rejects keys that appear twice in one object (nlohmann would silently keep
/// the last one, hiding a typo'd copy).
Json parseStrict(const std::string& text, const std::string& source) {
  std::vector<std::set<std::string>> keys_per_object;
  std::vector<std::string> path;
  std::string last_key;
  auto callback = [&](int /*depth*/, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
        keys_per_object.emplace_back();
        path.push_back(last_key);
        break;
      case Json::parse_event_t::object_end:
        keys_per_object.pop_back();
        path.pop_back();
        break;
      case Json::parse_event_t::key: {
        last_key = parsed.get<std::string>();
        if (!keys_per_object.empty() && !keys_per_object.back().insert(last_key).second) {
          std::string prefix;
          for (const std::string& p : path) prefix += p.empty() ? "" : p + ".";
          throwFormatError(source, prefix + last_key, "duplicate key");
        }
        break;
      }
      default:
        break;
    }
    return true;
  };
  try {
    return Json::parse(text, callback);
  } catch (const Json::parse_error& e) {
    std::string reason = e.what();
    const std::size_t colon = reason.rfind(": ");  // drop nlohmann's "[json.exception...]" prefix
    if (colon != std::string::npos) reason = reason.substr(colon + 2);
    throw FormatError(source + ": invalid JSON at " + position(text, e.byte) + ": " + reason);
  } catch (const Json::out_of_range& e) {
    // A number beyond a double (1e309): nlohmann gives neither the position nor the key.
    std::string reason = e.what();
    const std::size_t bracket = reason.find("] ");
    if (bracket != std::string::npos) reason = reason.substr(bracket + 2);
    throw FormatError(source + ": invalid JSON" +
                      (last_key.empty() ? "" : " after key '" + last_key + "'") + ": " + reason);
  }
}

/// Checks one object ("field" or "goal") against its rules and fills `dims`.
void readSection(const Json& root, const std::string& source, const std::string& section,
                 const std::vector<KeyRule>& rules, FieldDimensions& dims) {
  const Json& object = root.at(section);
  if (!object.is_object())
    throwFormatError(source, section, "expected an object, got " + typeName(object));
  for (const auto& item : object.items()) {
    const std::string key = section + "." + item.key();
    const auto outdated = kOutdatedNames.find(item.key());
    if (outdated != kOutdatedNames.end()) {
      throwFormatError(source, key, "outdated name, use " + section + "." + outdated->second);
    }
    bool known = false;
    for (const KeyRule& rule : rules) known = known || item.key() == rule.key;
    if (!known) throwFormatError(source, key, "unknown key");
  }
  for (const KeyRule& rule : rules) {
    const std::string key = section + "." + rule.key;
    if (!object.contains(rule.key)) {
      if (rule.optional) continue;
      throwFormatError(source, key, "missing");
    }
    const Json& value = object.at(rule.key);
    if (!value.is_number())
      throwFormatError(source, key, "expected a number, got " + typeName(value));
    const double v = value.get<double>();
    if (v == 0.0) throwFormatError(source, key, "must not be zero");
    if (rule.min_m == rule.max_m && v != rule.min_m) {
      throwFormatError(source, key,
                       "must be exactly " + shortest(rule.min_m) + ", got " + shortest(v));
    }
    if (v < rule.min_m || v > rule.max_m) {
      throwFormatError(source, key,
                       shortest(v) + " is out of range [" + shortest(rule.min_m) + ", " +
                           shortest(rule.max_m) + "]");
    }
    dims.*rule.member = v;
  }
}

}  // namespace

FieldDimensions parseSplFieldDimensions(const std::string& json_text,
                                        const std::string& source_name) {
  const Json root = parseStrict(json_text, source_name);
  if (!root.is_object()) {
    throw FormatError(source_name +
                      ": expected {\"field\": {...}, \"goal\": {...}} at the top level");
  }
  for (const auto& item : root.items()) {
    if (item.key() != "field" && item.key() != "goal")
      throwFormatError(source_name, item.key(), "unknown key");
  }
  for (const char* section : {"field", "goal"}) {
    if (!root.contains(section)) throwFormatError(source_name, section, "missing");
  }

  FieldDimensions dims;  // SPL defaults for what the JSON does not describe (mark shape, ...)
  dims.name = "SPL " + source_name.substr(source_name.find_last_of('/') + 1);
  readSection(root, source_name, "field", kFieldRules, dims);
  readSection(root, source_name, "goal", kGoalRules, dims);

  const Json& field = root.at("field");
  const bool has_length = field.contains("goalAreaLength");
  const bool has_width = field.contains("goalAreaWidth");
  if (has_length != has_width) {
    throwFormatError(
        source_name, has_length ? "field.goalAreaWidth" : "field.goalAreaLength",
        std::string("missing: goalAreaLength and goalAreaWidth come both or neither (") +
            (has_length ? "goalAreaLength" : "goalAreaWidth") + " is given)");
  }
  if (!has_length) {  // 2019 style: no goal areas
    dims.goal_area_length = 0.0;
    dims.goal_area_width = 0.0;
  }
  return dims;
}

FieldDimensions readSplFieldDimensions(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FormatError(path + ": cannot open for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return parseSplFieldDimensions(text.str(), path);
}

std::string splFieldDimensionsToJson(const FieldDimensions& dims) {
  Json root = {{"field", Json::object()}, {"goal", Json::object()}};
  const bool goal_area = dims.goal_area_length > 0.0 || dims.goal_area_width > 0.0;
  auto write = [&](const char* section, const std::vector<KeyRule>& rules) {
    for (const KeyRule& rule : rules) {
      if (rule.optional && !goal_area) continue;
      root[section][rule.key] = dims.*rule.member;
    }
  };
  write("field", kFieldRules);
  write("goal", kGoalRules);
  std::string text = root.dump(2) + "\n";
  // The same rules as reading: an export that would not load again is an error, not a file.
  parseSplFieldDimensions(text, "field_dimensions.json");
  return text;
}

FieldModel importSplField(const std::string& path) {
  return makeField(readSplFieldDimensions(path));
}

}  // namespace houghloc
