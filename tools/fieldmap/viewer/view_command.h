#pragma once

#include <CLI/CLI.hpp>

namespace houghloc::fieldmap {

/// Registers `view [--field FILE | --standard NAME] [--lcm-url URL] [--channel-prefix P]...
/// [--log FILE] [--screenshot PNG]`: the live viewer over LCM, or a replay of a log.
void addViewCommand(CLI::App& app, int& exit_code);

}  // namespace houghloc::fieldmap
