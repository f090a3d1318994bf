# Renders the houghloc-play fixture once per build tree (cmake -P; CTest FIXTURES_SETUP).
#   -DRENDER=<houghloc-render> -DOUT=<folder>
# A NAO's two cameras taking turns (camera ids), with ground truth; 30 frames = 1 s.
include(${CMAKE_CURRENT_LIST_DIR}/../../../cmake/RenderFixtureList.cmake)
render_fixture_list(30 "spl_nao_walk|--standard spl --camera nao --trajectory walk --seed 401")
