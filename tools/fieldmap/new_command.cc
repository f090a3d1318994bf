// `new --standard NAME -o FILE`: writes a standard field's map.
#include <iostream>
#include <memory>

#include "field_models/field_yaml.h"
#include "field_models/standard_fields.h"
#include "tools/fieldmap/commands.h"

namespace houghloc::fieldmap {

void addNewCommand(CLI::App& app, int& exit_code) {
  struct Options {
    std::string standard;
    std::string output;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command =
      app.add_subcommand("new",
                         "Write the map of a standard field (DESIGN 4 table) as YAML.\n"
                         "Example: houghloc-fieldmap new --standard spl -o spl.yaml");
  command->add_option("--standard", options->standard, "Standard field")
      ->required()
      ->check(CLI::IsMember(standardFieldNames()));
  command->add_option("-o,--output", options->output, "Map file to write (.yaml)")->required();
  command->callback([options, &exit_code] {
    const FieldModel field = makeStandardField(options->standard);
    writeFieldYaml(field, options->output);
    std::cout << "wrote " << options->output << " (" << summarize(field) << ")\n";
    exit_code = 0;
  });
}

}  // namespace houghloc::fieldmap
