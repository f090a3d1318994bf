#pragma once

namespace houghloc {

/// pi (M_PI is POSIX, not standard C++17) and one degree in radians.
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

}  // namespace houghloc
