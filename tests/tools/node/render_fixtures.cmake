# Renders the houghloc-node fixture once per build tree (cmake -P; CTest FIXTURES_SETUP).
#   -DRENDER=<houghloc-render> -DOUT=<folder>
# One nao-top camera walking for 10 s (300 frames at 30 Hz), played at real time.
include(${CMAKE_CURRENT_LIST_DIR}/../../../cmake/RenderFixtureList.cmake)
render_fixture_list(300 "spl_nao-top_walk|--standard spl --camera nao-top --trajectory walk --seed 402")
