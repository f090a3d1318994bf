# Common compile settings, attached to targets (no global flags, DESIGN §9).
add_library(houghloc_options INTERFACE)
target_compile_features(houghloc_options INTERFACE cxx_std_17)
target_compile_options(houghloc_options INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wno-deprecated-enum-enum-conversion>)

option(HOUGHLOC_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if(HOUGHLOC_SANITIZE)
  target_compile_options(houghloc_options INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(houghloc_options INTERFACE -fsanitize=address,undefined)
endif()

# libFuzzer targets of tests/fuzz (clang only; the `fuzz` preset). Every library gets the
# fuzzer's coverage instrumentation; the targets themselves link -fsanitize=fuzzer.
option(HOUGHLOC_BUILD_FUZZ "Build the libFuzzer targets of tests/fuzz (clang)" OFF)
if(HOUGHLOC_BUILD_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "HOUGHLOC_BUILD_FUZZ needs clang (e.g. -DCMAKE_CXX_COMPILER=clang++-14)")
  endif()
  target_compile_options(houghloc_options INTERFACE -fsanitize=fuzzer-no-link)
endif()

# houghloc_add_library(NAME SOURCES ... DEPS ...): one library per folder (DESIGN §2).
function(houghloc_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>)
  target_link_libraries(${name} PUBLIC houghloc_options ${ARG_DEPS})
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()
