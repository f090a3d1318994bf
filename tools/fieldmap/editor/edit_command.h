#pragma once

#include <CLI/CLI.hpp>

namespace houghloc::fieldmap {

/// Registers `edit [FILE] [--standard NAME] [--check FOLDER [--frame N]] [--screenshot PNG]`:
/// opens the Qt editor on a YAML
/// map or field_dimensions.json, or on a standard field (default spl).
void addEditCommand(CLI::App& app, int& exit_code);

}  // namespace houghloc::fieldmap
