#include "field_models/yaml_precheck.h"

#include <yaml.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <sstream>

#include "field_models/format_error.h"

namespace houghloc {
namespace {

/// OpenCV writes "%YAML:1.0", which YAML 1.1 parsers reject ("%YAML 1.0" is the directive).
/// Blanked rather than removed, so that libyaml's line numbers stay those of the file.
std::string withoutOpenCvHeader(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos || text.compare(first, 6, "%YAML:") != 0) return text;
  std::string blanked = text;
  const std::size_t end = blanked.find('\n', first);
  blanked.replace(first, (end == std::string::npos ? blanked.size() : end) - first, "");
  return blanked;
}

/// OpenCV reads the version of "%YAML:<major>.<minor>" with std::stoi, which throws
/// std::out_of_range (message "stoi", no file) on a long run of digits (tests/fuzz/field_yaml):
/// only "%YAML:1.<digits>" is accepted.
void checkOpenCvHeader(const std::string& text, const std::string& source_name) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos || text.compare(first, 6, "%YAML:") != 0) return;
  const std::size_t end = std::min(text.find('\n', first), text.size());
  std::string header = text.substr(first, end - first);
  header.erase(header.find_last_not_of(" \t\r") + 1);
  const std::string version = header.substr(6);
  const bool ok = version.size() >= 3 && version.size() <= 6 && version.compare(0, 2, "1.") == 0 &&
                  version.find_first_not_of("0123456789", 2) == std::string::npos;
  if (!ok) {
    const auto line = 1 + std::count(text.begin(), text.begin() + first, '\n');
    throw FormatError(source_name + ": line " + std::to_string(line) +
                      ": expected the header %YAML:1.0, not '" + header.substr(0, 40) + "'");
  }
}

void checkParsesAsMap(const std::string& text, const std::string& source_name) {
  yaml_parser_t parser;
  if (!yaml_parser_initialize(&parser)) throw FormatError(source_name + ": out of memory");
  const std::unique_ptr<yaml_parser_t, void (*)(yaml_parser_t*)> owner(&parser, yaml_parser_delete);
  const std::string yaml = withoutOpenCvHeader(text);
  yaml_parser_set_input_string(&parser, reinterpret_cast<const unsigned char*>(yaml.data()),
                               yaml.size());
  bool root_seen = false;
  for (;;) {
    yaml_event_t event;
    if (!yaml_parser_parse(&parser, &event)) {
      throw FormatError(source_name + ": line " + std::to_string(parser.problem_mark.line + 1) +
                        ": not valid YAML (" + (parser.problem ? parser.problem : "parse error") +
                        ")");
    }
    const yaml_event_type_t type = event.type;
    const std::size_t line = event.start_mark.line + 1;
    yaml_event_delete(&event);
    if (type == YAML_STREAM_END_EVENT) return;
    if (type == YAML_SCALAR_EVENT || type == YAML_SEQUENCE_START_EVENT ||
        type == YAML_ALIAS_EVENT || type == YAML_MAPPING_START_EVENT) {
      if (!root_seen && type != YAML_MAPPING_START_EVENT) {
        throw FormatError(source_name + ": line " + std::to_string(line) +
                          ": expected a map of keys at the top level");
      }
      root_seen = true;
    }
    if (type == YAML_DOCUMENT_END_EVENT) root_seen = false;  // each document is a map
  }
}

void checkIndentation(const std::string& text, const std::string& source_name) {
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  int first_line = 0;
  std::size_t first_indent = 0;
  while (std::getline(lines, line)) {
    ++number;
    const std::size_t indent = line.find_first_not_of(" \t\r");
    if (indent == std::string::npos || line[indent] == '#') continue;
    if (first_line == 0) {
      if (line[indent] == '{') return;  // JSON
      if (line[indent] == '%') continue;
      std::size_t content = indent;
      if (line.compare(indent, 3, "---") == 0) {
        // "--- key: value" starts the document with content at its column
        content = line.find_first_not_of(" \t\r", indent + 3);
        if (content == std::string::npos || line[content] == '#') continue;
      }
      first_line = number;
      first_indent = content;
    } else if (indent < first_indent) {
      throw FormatError(source_name + ": line " + std::to_string(number) +
                        ": indented less than the first key (line " + std::to_string(first_line) +
                        ")");
    }
  }
}

}  // namespace

void checkYamlBeforeFileStorage(const std::string& text, const std::string& source_name) {
  checkOpenCvHeader(text, source_name);
  checkIndentation(text, source_name);
  checkParsesAsMap(text, source_name);
}

std::string readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace houghloc
