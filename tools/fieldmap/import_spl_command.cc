// `import-spl FILE -o FILE`: converts the RoboCup SPL field_dimensions.json into a map.
#include <iostream>
#include <memory>
#include <stdexcept>

#include "field_models/field_yaml.h"
#include "field_models/spl_import.h"
#include "tools/fieldmap/commands.h"

namespace houghloc::fieldmap {

void addImportSplCommand(CLI::App& app, int& exit_code) {
  struct Options {
    std::string input;
    std::string output;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "import-spl",
      "Import a RoboCup SPL field_dimensions.json (rules in docs/formats.md) and write the map.\n"
      "Example: houghloc-fieldmap import-spl field_dimensions.json -o field.yaml");
  command->add_option("FILE", options->input, "field_dimensions.json to read")->required();
  command->add_option("-o,--output", options->output, "Map file to write (.yaml)")->required();
  command->callback([options, &exit_code] {
    const FieldModel field = importSplField(options->input);
    // The ranges allow e.g. a penalty area wider than the field: refuse such maps here rather
    // than write a file that `validate` rejects.
    const std::vector<std::string> issues = describeIssues(field, options->input);
    if (!issues.empty()) {
      for (const std::string& issue : issues) std::cerr << issue << "\n";
      throw std::runtime_error(options->input + ": the dimensions give an invalid map; " +
                               options->output + " not written");
    }
    writeFieldYaml(field, options->output);
    std::cout << "wrote " << options->output << " (" << summarize(field) << ")\n";
    exit_code = 0;
  });
}

}  // namespace houghloc::fieldmap
