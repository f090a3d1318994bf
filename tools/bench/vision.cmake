# houghloc-bench-vision: VisionPipeline::process() against a stock-OpenCV baseline (issue 5) on
# rendered 640x480 (nao-top) and 1280x720 (adult) frames, rendered into the build tree on first
# use with houghloc-render.
if(TARGET houghloc-render AND TARGET houghloc_offline)
  add_executable(houghloc-bench-vision ${CMAKE_CURRENT_LIST_DIR}/vision_bench.cc
    ${CMAKE_CURRENT_LIST_DIR}/vision_baseline.cc)
  target_link_libraries(houghloc-bench-vision PRIVATE houghloc_options houghloc_vision
    houghloc_offline houghloc_recording benchmark::benchmark opencv_core opencv_imgproc
    opencv_imgcodecs opencv_calib3d)
  target_compile_definitions(houghloc-bench-vision PRIVATE
    HOUGHLOC_RENDER_EXE="$<TARGET_FILE:houghloc-render>"
    HOUGHLOC_BENCH_DIR="${PROJECT_BINARY_DIR}/fixtures/bench")
  add_dependencies(houghloc-bench-vision houghloc-render)
endif()
