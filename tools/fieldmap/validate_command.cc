// `validate FILE`: reads a map and lists its problems; exit status 1 when there are any.
#include <iostream>
#include <memory>

#include "field_models/field_yaml.h"
#include "tools/fieldmap/commands.h"

namespace houghloc::fieldmap {

void addValidateCommand(CLI::App& app, int& exit_code) {
  auto input = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "validate",
      "Check a map: format, finite numbers, degenerate or duplicate segments, arcs, marks, "
      "features outside the field plus border. Prints one line per issue on stderr and exits "
      "with 1 if there is any.\nExample: houghloc-fieldmap validate field.yaml");
  command->add_option("FILE", *input, "Map file (.yaml)")->required();
  command->callback([input, &exit_code] {
    const FieldModel field = readFieldYaml(*input);
    const std::vector<std::string> issues = describeIssues(field, *input);
    for (const std::string& issue : issues) std::cerr << issue << "\n";
    if (issues.empty()) {
      std::cout << *input << ": valid (" << summarize(field) << ")\n";
      exit_code = 0;
    } else {
      std::cerr << *input << ": " << issues.size() << " issue(s)\n";
      exit_code = 1;
    }
  });
}

}  // namespace houghloc::fieldmap
