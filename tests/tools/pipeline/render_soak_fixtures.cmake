# Renders the soak test's recordings once per build tree (cmake -P; CTest FIXTURES_SETUP).
#   -DRENDER=<houghloc-render> -DOUT=<folder>
# Two loops of one nao-top camera at 30 Hz: two kidnaps in 5 s, and a 3 s fall in 6 s.
include(${CMAKE_CURRENT_LIST_DIR}/../../../cmake/RenderFixtureList.cmake)
render_fixture_list(150 "spl_nao-top_kidnap|--standard spl --camera nao-top --trajectory kidnap --seed 501")
render_fixture_list(180 "spl_nao-top_fall|--standard spl --camera nao-top --trajectory fall --seed 502")
