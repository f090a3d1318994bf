// Where the tests labelled `real` find the real robot frames: ../shared/data/real, never copied
// into the repository. HOUGHLOC_REAL_DATA is that folder's absolute path
// (tests/real/CMakeLists.txt).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace houghloc {

inline bool realDataPresent() {
  return std::filesystem::exists(std::filesystem::path(HOUGHLOC_REAL_DATA) / "index.csv");
}

inline bool runningOnCi() {
  const char* ci = std::getenv("CI");
  return ci && std::strcmp(ci, "true") == 0;
}

}  // namespace houghloc

// With CI=true a missing folder fails; elsewhere the test is skipped with a message.
#define REQUIRE_REAL_DATA()                                                                   \
  do {                                                                                        \
    if (!::houghloc::realDataPresent()) {                                                     \
      if (::houghloc::runningOnCi()) FAIL() << HOUGHLOC_REAL_DATA << ": real frames missing"; \
      GTEST_SKIP() << "real frames not found at " << HOUGHLOC_REAL_DATA;                      \
    }                                                                                         \
  } while (false)
