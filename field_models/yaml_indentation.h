#pragma once

#include <string>

namespace houghloc {

/// Rejects YAML text in which a line is indented less than the first key (after the %YAML and
/// --- lines; blank and comment lines do not count). Such text is not valid YAML, and OpenCV
/// 4.6's cv::FileStorage reader loops forever on some of it (e.g. " c: 1\n-x\n-" or "---o:
/// 1\n--\n-", found by tests/fuzz/field_yaml), so every reader calls this before handing text to
/// FileStorage. Text starting with '{' (JSON) is not checked. Throws FormatError
/// "<source>:<line>: indented less than the first key (line <n>)".
void checkYamlIndentation(const std::string& text, const std::string& source_name);

/// Reads a whole file as text; an unreadable file gives "" (callers report missing files).
std::string readTextFile(const std::string& path);

}  // namespace houghloc
