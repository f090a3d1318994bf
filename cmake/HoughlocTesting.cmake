# Where the rendered test fixtures live (tests/*/render_fixtures.cmake render them once per folder,
# a .complete stamp per fixture). A sanitizer or fuzz tree points it at the Release tree's folder,
# e.g. -DHOUGHLOC_FIXTURE_DIR=$PWD/build/fixtures, and so renders nothing again.
set(HOUGHLOC_FIXTURE_DIR "${PROJECT_BINARY_DIR}/fixtures" CACHE PATH
  "Folder of the rendered test fixtures (shared between build trees)")

option(HOUGHLOC_UNIT_TESTS_ONLY "Build and register only the test binaries labelled unit" OFF)

# houghloc_add_test(NAME LABELS unit|accuracy|slow SOURCES ... DEPS ... [TIMEOUT s])
# Builds one GoogleTest binary and registers each test case with ctest under the given labels.
function(houghloc_add_test name)
  cmake_parse_arguments(ARG "" "TIMEOUT" "LABELS;SOURCES;DEPS" ${ARGN})
  if(NOT ARG_LABELS)
    set(ARG_LABELS unit)
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  # A tree that runs only the unit tests (the sanitizer tree) keeps the other test binaries as
  # targets, so that the lines that configure them still apply, but neither builds nor lists them.
  set(unlisted "")
  if(HOUGHLOC_UNIT_TESTS_ONLY AND NOT "unit" IN_LIST ARG_LABELS)
    set(unlisted EXCLUDE_FROM_ALL)
  endif()
  add_executable(${name} ${unlisted} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE houghloc_options GTest::gtest GTest::gtest_main ${ARG_DEPS})
  target_compile_definitions(${name} PRIVATE
    HOUGHLOC_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    HOUGHLOC_BINARY_DIR="${PROJECT_BINARY_DIR}")
  if(unlisted)
    return()
  endif()
  gtest_discover_tests(${name}
    DISCOVERY_TIMEOUT 60
    PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT ${ARG_TIMEOUT})
endfunction()
