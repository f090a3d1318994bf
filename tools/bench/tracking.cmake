# houghloc-bench-tracking: HypothesisTracker update vs a reference MCL (issue 8).
# The synthetic walk comes from the tracker tests' generator until tools/synthetic lands.
add_executable(houghloc-bench-tracking
  ${CMAKE_CURRENT_LIST_DIR}/tracking_bench.cc
  ${CMAKE_CURRENT_LIST_DIR}/mcl_baseline.cc
  ${PROJECT_SOURCE_DIR}/tests/localization/tracking_scenario.cc)
target_link_libraries(houghloc-bench-tracking PRIVATE
  houghloc_options houghloc_localization benchmark::benchmark)
