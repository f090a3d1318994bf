#include "field_models/field_yaml.h"

#include <cmath>
#include <fstream>
#include <opencv2/core.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

#include "field_models/yaml_precheck.h"

namespace houghloc {
namespace {

// FileStorage only reads YAML that starts with this header; hand-written maps often lack it.
constexpr char kYamlHeader[] = "%YAML:1.0\n---\n";
constexpr int kYamlHeaderLines = 2;

const std::set<std::string> kKnownKeys = {
    "name",     "field_length", "field_width", "line_width", "border_strip_width",
    "segments", "arcs",         "marks",       "goals"};

bool isNumber(const cv::FileNode& node) { return node.isInt() || node.isReal(); }

double readScalar(const cv::FileNode& root, const std::string& source, const std::string& key) {
  const cv::FileNode node = root[key];
  if (node.empty() || node.isNone()) throwFormatError(source, key, "missing");
  if (!isNumber(node)) throwFormatError(source, key, "expected a number");
  return node.real();
}

/// One list entry: a flow sequence of exactly `count` numbers.
std::vector<double> readRow(const cv::FileNode& node, const std::string& source,
                            const std::string& entry, std::size_t count) {
  const std::string expected = "expected " + std::to_string(count) + " numbers";
  if (!node.isSeq()) throwFormatError(source, entry, expected + " in [ ]");
  if (node.size() != count) {
    throwFormatError(source, entry, expected + ", got " + std::to_string(node.size()));
  }
  std::vector<double> row;
  for (std::size_t i = 0; i < count; ++i) {
    const cv::FileNode value = node[static_cast<int>(i)];
    if (!isNumber(value))
      throwFormatError(source, entry, expected + "; item " + std::to_string(i) + " is not");
    row.push_back(value.real());
  }
  return row;
}

/// Calls `add(row, entry)` for each entry of the list `key`; a missing optional list is empty.
template <typename AddRow>
void readList(const cv::FileNode& root, const std::string& source, const std::string& key,
              std::size_t count, bool required, AddRow add) {
  const cv::FileNode list = root[key];
  if (list.empty() || list.isNone()) {
    if (required) throwFormatError(source, key, "missing");
    return;
  }
  if (!list.isSeq()) throwFormatError(source, key, "expected a list");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string entry = key + "[" + std::to_string(i) + "]";
    add(readRow(list[static_cast<int>(i)], source, entry, count), entry);
  }
}

MarkShape readShape(double value, const std::string& source, const std::string& entry) {
  if (value == 0.0) return MarkShape::kCross;
  if (value == 1.0) return MarkShape::kDot;
  throwFormatError(source, entry, "shape must be 0 (cross) or 1 (dot)");
}

/// Turns FileStorage's parse exception into "source: line N: reason". OpenCV 4.6 puts
/// "<file>(<line>): <reason>" into cv::Exception::func, so both fields are searched.
[[noreturn]] void rethrowParseError(const cv::Exception& e, const std::string& source,
                                    int line_offset) {
  // OpenCV writes "(<line>): <reason>"; the digit count is bounded because the reason may quote
  // the file, whose own "(<digits>): " must not reach stoi (tests/fuzz field_yaml).
  static const std::regex kLineReason(R"(\((\d{1,9})\): (.*))");
  std::smatch match;
  for (const std::string& text : {e.func, e.err}) {
    if (std::regex_search(text, match, kLineReason)) {
      const int line = std::max(1, std::stoi(match[1].str()) - line_offset);
      throw FormatError(source + ": line " + std::to_string(line) + ": " + match[2].str());
    }
  }
  throw FormatError(source + ": not a readable YAML map (" + e.err + ")");
}

FieldModel parseRoot(const cv::FileNode& root, const std::string& source) {
  if (!root.isMap()) throw FormatError(source + ": expected a YAML map of keys at the top level");
  if (!root["field"].empty() && !root["goal"].empty()) {
    throw FormatError(source +
                      ": field: unknown key (this looks like an SPL "
                      "field_dimensions.json, which must be imported, not read as a map)");
  }
  std::set<std::string> seen;
  for (const std::string& key : root.keys()) {
    if (!kKnownKeys.count(key)) throwFormatError(source, key, "unknown key");
    // FileStorage would silently use the first of two equal keys.
    if (!seen.insert(key).second) throwFormatError(source, key, "duplicate key");
  }
  FieldModel field;
  const cv::FileNode name = root["name"];
  if (!name.empty() && !name.isNone()) {
    if (!name.isString()) throwFormatError(source, "name", "expected a string");
    field.name = name.string();
  }
  field.field_length = readScalar(root, source, "field_length");
  field.field_width = readScalar(root, source, "field_width");
  field.line_width = readScalar(root, source, "line_width");
  field.border_strip_width = readScalar(root, source, "border_strip_width");

  readList(root, source, "segments", 4, true, [&](const std::vector<double>& v, auto&) {
    field.segments.push_back(Segment2{Eigen::Vector2d(v[0], v[1]), Eigen::Vector2d(v[2], v[3])});
  });
  readList(root, source, "arcs", 5, false, [&](const std::vector<double>& v, auto&) {
    field.arcs.push_back(Arc2{Eigen::Vector2d(v[0], v[1]), v[2], v[3], v[4]});
  });
  readList(root, source, "marks", 4, false,
           [&](const std::vector<double>& v, const std::string& entry) {
             field.marks.push_back(
                 Mark{Eigen::Vector2d(v[0], v[1]), v[2], readShape(v[3], source, entry)});
           });
  readList(root, source, "goals", 6, false, [&](const std::vector<double>& v, auto&) {
    field.goals.push_back(Goal{Eigen::Vector2d(v[0], v[1]), v[2], v[3], v[4], v[5]});
  });
  return field;
}

}  // namespace

FieldModel parseFieldYaml(const std::string& text, const std::string& source_name) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) throw FormatError(source_name + ": empty file");
  const bool has_header = text[first] == '%' || text[first] == '{';  // YAML header or JSON
  const std::string full = has_header ? text : kYamlHeader + text;
  checkYamlBeforeFileStorage(text, source_name);
  try {
    cv::FileStorage fs(full, cv::FileStorage::READ | cv::FileStorage::MEMORY);
    if (!fs.isOpened()) throw FormatError(source_name + ": not a readable YAML map");
    return parseRoot(fs.root(), source_name);
  } catch (const cv::Exception& e) {
    rethrowParseError(e, source_name, has_header ? 0 : kYamlHeaderLines);
  }
}

FieldModel readFieldYaml(const std::string& path) {
  // Read the text ourselves: FileStorage logs to stderr when a file is missing, and libraries
  // must not print (DESIGN §2).
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FormatError(path + ": cannot open for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return parseFieldYaml(text.str(), path);
}

std::string fieldToYaml(const FieldModel& field) {
  if (field.name.find_first_of("\"\r\n") != std::string::npos) {
    throw FormatError("name: must not contain double quotes or line breaks");
  }
  cv::FileStorage fs("field.yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY |
                                       cv::FileStorage::FORMAT_YAML);
  fs.writeComment("houghloc field-line map (DESIGN 4): field frame, centre-line coordinates, m");
  fs << "name" << field.name;
  fs << "field_length" << field.field_length;
  fs << "field_width" << field.field_width;
  fs << "line_width" << field.line_width;
  fs << "border_strip_width" << field.border_strip_width;

  fs.writeComment("x1, y1, x2, y2");
  fs << "segments"
     << "[";
  for (const Segment2& s : field.segments) {
    fs << "[:" << s.a.x() << s.a.y() << s.b.x() << s.b.y() << "]";
  }
  fs << "]";
  fs.writeComment("cx, cy, radius, start in (-pi, pi], sweep in (0, 2pi] (counter-clockwise)");
  fs << "arcs"
     << "[";
  for (const Arc2& a : field.arcs) {
    fs << "[:" << a.center.x() << a.center.y() << a.radius << a.start_rad << a.sweep_rad << "]";
  }
  fs << "]";
  fs.writeComment("cx, cy, size, shape (0 = cross, 1 = filled dot)");
  fs << "marks"
     << "[";
  for (const Mark& m : field.marks) {
    fs << "[:" << m.center.x() << m.center.y() << m.size << static_cast<int>(m.shape) << "]";
  }
  fs << "]";
  fs.writeComment("cx, cy, inner_width, post_diameter, height, depth (display only)");
  fs << "goals"
     << "[";
  for (const Goal& g : field.goals) {
    fs << "[:" << g.center.x() << g.center.y() << g.inner_width << g.post_diameter << g.height
       << g.depth << "]";
  }
  fs << "]";
  return fs.releaseAndGetString();
}

void writeFieldYaml(const FieldModel& field, const std::string& path) {
  const std::string text = fieldToYaml(field);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw FormatError(path + ": cannot open for writing");
  out << text;
  out.close();
  if (!out) throw FormatError(path + ": write failed");
}

}  // namespace houghloc
