#pragma once

#include <string>

namespace houghloc {

/// OpenCV 4.6's cv::FileStorage reader loops forever or misreads memory on some malformed YAML
/// (tests/fuzz/field_yaml found three patterns), so every reader hands its text to FileStorage
/// only after this check passes. Two gates:
///  - libyaml (the reference C parser) must parse the text, and its root must be a map of keys
///    (every houghloc YAML file is one); OpenCV's "%YAML:1.0" header is accepted;
///  - no line may be indented less than the first key (after the header and --- lines; blank
///    and comment lines do not count): FileStorage misreads such text even where YAML allows it.
/// Throws FormatError "<source>: line <n>: <what is wrong>" (the line as in `text`).
void checkYamlBeforeFileStorage(const std::string& text, const std::string& source_name);

/// Reads a whole file as text; an unreadable file gives "" (callers report missing files).
std::string readTextFile(const std::string& path);

}  // namespace houghloc
