#pragma once

#include <cstdint>

namespace houghloc {

/// CLOCK_MONOTONIC in microseconds: the clock images are stamped with on a robot (DESIGN §7).
std::int64_t monotonicMicros();

}  // namespace houghloc
