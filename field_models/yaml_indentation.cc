#include "field_models/yaml_indentation.h"

#include <fstream>
#include <sstream>

#include "field_models/format_error.h"

namespace houghloc {

void checkYamlIndentation(const std::string& text, const std::string& source_name) {
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
      throw FormatError(source_name + ":" + std::to_string(number) +
                        ": indented less than the first key (line " + std::to_string(first_line) +
                        ")");
    }
  }
}

std::string readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace houghloc
