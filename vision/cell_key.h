#pragma once

#include <cstdint>

namespace houghloc {

/// One number per cell of a square grid (cell indices within +-2^31): both indices packed,
/// shifted as unsigned (a negative index shifted is UB).
inline std::int64_t cellKey(std::int64_t cx, std::int64_t cy) {
  return static_cast<std::int64_t>((static_cast<std::uint64_t>(cx) << 32) ^
                                   (static_cast<std::uint64_t>(cy) & 0xffffffffu));
}

}  // namespace houghloc
