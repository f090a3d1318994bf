// The scenario YAML of houghloc-render (DESIGN §5.4): load and validate arbitrary text.
#include <exception>

#include "tests/fuzz/fuzz_support.h"
#include "tools/render/scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace houghloc;
  const std::string path = fuzz::writeScratchFile(
      "scenario.yaml", std::string(reinterpret_cast<const char*>(data), size));
  try {
    validateScenario(loadScenario(path));
  } catch (const std::invalid_argument&) {
    // validateScenario names the member, not the file (the caller adds the file)
  } catch (const std::exception& e) {
    fuzz::requireNamed(e.what(), "scenario.yaml");
  }
  return 0;
}
