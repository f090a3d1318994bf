#pragma once

#include <stdexcept>
#include <string>

namespace houghloc {

/// A map or field-dimensions file that cannot be read. The message names the file and the entry at
/// fault, e.g. "field.yaml: segments[3]: expected 4 numbers, got 3" (DESIGN §2).
class FormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws FormatError("<source>: <entry>: <what>").
[[noreturn]] inline void throwFormatError(const std::string& source, const std::string& entry,
                                          const std::string& what) {
  throw FormatError(source + ": " + entry + ": " + what);
}

}  // namespace houghloc
