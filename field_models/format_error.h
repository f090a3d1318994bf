#pragma once

#include <stdexcept>

namespace houghloc {

/// A map or field-dimensions file that cannot be read. The message names the file and the entry at
/// fault, e.g. "field.yaml: segments[3]: expected 4 numbers, got 3" (DESIGN §2).
class FormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace houghloc
