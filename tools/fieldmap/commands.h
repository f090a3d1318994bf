#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "field_models/field_model.h"

namespace houghloc::fieldmap {

/// Each add...Command() registers one subcommand on `app`. Its callback throws std::exception on
/// invalid input (main prints the message and exits non-zero) and sets `exit_code` otherwise.
void addNewCommand(CLI::App& app, int& exit_code);
void addImportSplCommand(CLI::App& app, int& exit_code);
void addValidateCommand(CLI::App& app, int& exit_code);
void addRenderCommand(CLI::App& app, int& exit_code);

/// "<file>: <issue>" lines for every validation issue of the map; empty when it is valid.
std::vector<std::string> describeIssues(const FieldModel& field, const std::string& file);

/// A one-line summary, e.g. "SPL 2020: 9 x 6 m, 17 segments, 1 arcs, 3 marks, 2 goals".
std::string summarize(const FieldModel& field);

}  // namespace houghloc::fieldmap
