// Field map YAML (DESIGN §4): parse, validate and write back arbitrary text.
#include <exception>

#include "field_models/field_validation.h"
#include "field_models/field_yaml.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace houghloc;
  const std::string text(reinterpret_cast<const char*>(data), size);
  FieldModel field;
  try {
    field = parseFieldYaml(text, "fuzz_field.yaml");
  } catch (const std::exception& e) {
    fuzz::requireNamed(e.what(), "fuzz_field.yaml");
    return 0;
  }
  validateField(field);  // must not crash on any parsed map, valid or not
  try {
    const FieldModel again = parseFieldYaml(fieldToYaml(field), "again.yaml");
    if (again.segments.size() != field.segments.size()) fuzz::fail("write-read lost segments");
  } catch (const FormatError&) {
    // names with quotes or line breaks cannot be written back (documented)
  }
  return 0;
}
