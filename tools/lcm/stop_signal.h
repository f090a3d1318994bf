#pragma once

#include <atomic>

namespace houghloc {

/// Makes SIGINT and SIGTERM set the returned flag (for the executables' clean exit).
const std::atomic<bool>& installStopSignals();

}  // namespace houghloc
