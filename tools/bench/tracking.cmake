# houghloc-bench-tracking: HypothesisTracker update vs a reference MCL (issue 8), on a synthetic
# walk (the tracker tests' generator) and on rendered recordings (--recording=DIR), which are read
# and run through vision with houghloc-offline's library (houghloc_offline).
add_executable(houghloc-bench-tracking
  ${CMAKE_CURRENT_LIST_DIR}/tracking_bench.cc
  ${CMAKE_CURRENT_LIST_DIR}/tracking_recording.cc
  ${CMAKE_CURRENT_LIST_DIR}/tracking_compare.cc
  ${CMAKE_CURRENT_LIST_DIR}/mcl_baseline.cc
  ${PROJECT_SOURCE_DIR}/tests/localization/tracking_scenario.cc)
target_link_libraries(houghloc-bench-tracking PRIVATE
  houghloc_options houghloc_localization houghloc_offline benchmark::benchmark)
