// houghloc-fieldmap: creates, imports, validates and renders field-line maps (DESIGN §4, §6).
#include <exception>
#include <iostream>
#include <sstream>

#include "field_models/field_validation.h"
#include "tools/fieldmap/commands.h"
#ifdef HOUGHLOC_WITH_EDITOR
#include "tools/fieldmap/editor/edit_command.h"
#include "tools/fieldmap/viewer/view_command.h"
#endif

namespace houghloc::fieldmap {

std::vector<std::string> describeIssues(const FieldModel& field, const std::string& file) {
  std::vector<std::string> lines;
  for (const FieldIssue& issue : validateField(field))
    lines.push_back(file + ": " + issue.toString());
  return lines;
}

std::string summarize(const FieldModel& field) {
  std::ostringstream out;
  out << (field.name.empty() ? "(unnamed)" : field.name) << ": " << field.field_length << " x "
      << field.field_width << " m, " << field.segments.size() << " segments, " << field.arcs.size()
      << " arcs, " << field.marks.size() << " marks, " << field.goals.size() << " goals";
  return out.str();
}

}  // namespace houghloc::fieldmap

int main(int argc, char** argv) {
  using namespace houghloc::fieldmap;
  CLI::App app{
      "houghloc-fieldmap: create, import, validate and render houghloc field-line maps (YAML, "
      "see docs/formats.md).",
      "houghloc-fieldmap"};
  app.require_subcommand(1);
  int exit_code = 0;
  addNewCommand(app, exit_code);
  addImportSplCommand(app, exit_code);
  addValidateCommand(app, exit_code);
  addRenderCommand(app, exit_code);
#ifdef HOUGHLOC_WITH_EDITOR
  addEditCommand(app, exit_code);
  addViewCommand(app, exit_code);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "houghloc-fieldmap: " << e.what() << "\n";
    return 1;
  }
  return exit_code;
}
