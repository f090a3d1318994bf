// SPL field_dimensions.json import (DESIGN §4): parse arbitrary text, build the map.
#include <exception>

#include "field_models/field_validation.h"
#include "field_models/spl_import.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace houghloc;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const FieldDimensions dims = parseSplFieldDimensions(text, "fuzz_dimensions.json");
    validateField(makeField(dims));
  } catch (const std::exception& e) {
    fuzz::requireNamed(e.what(), "fuzz_dimensions.json");
  }
  return 0;
}
