# houghloc-bench-global: GlobalHoughLocalizer::locate() against its baselines (issue 6):
# cv::HoughLinesPointSet for step 1 and the exhaustive grid search for the whole localization.
add_executable(houghloc-bench-global ${CMAKE_CURRENT_LIST_DIR}/global_bench.cc)
target_link_libraries(houghloc-bench-global PRIVATE houghloc_options houghloc_localization
  houghloc_synthetic houghloc_baselines benchmark::benchmark opencv_core opencv_imgproc)

# houghloc-global-dump: every hypothesis of a fixed set of synthetic frames, for `cmp` of builds.
add_executable(houghloc-global-dump ${CMAKE_CURRENT_LIST_DIR}/global_dump.cc)
target_link_libraries(houghloc-global-dump PRIVATE houghloc_options houghloc_localization
  houghloc_synthetic CLI11::CLI11)
