# Renders the latency fixture once per build tree (cmake -P; CTest FIXTURES_SETUP).
#   -DRENDER=<houghloc-render> -DOUT=<folder>
# Two 640x480 NAO cameras at 30 Hz each (latency_scenario.yaml: 60 frames/s taking turns), 10 s.
include(${CMAKE_CURRENT_LIST_DIR}/../../../cmake/RenderFixtureList.cmake)
render_fixture_list(600 "spl_nao_60fps|--scenario ${CMAKE_CURRENT_LIST_DIR}/latency_scenario.yaml --standard spl --camera nao")
