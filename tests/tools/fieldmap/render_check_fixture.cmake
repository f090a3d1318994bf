# Renders the editor check's fixture once per build tree (cmake -P; CTest FIXTURES_SETUP).
#   -DRENDER=<houghloc-render> -DOUT=<folder> -DSCENARIO_DIR=<tests/tools/fieldmap/data>
include(${CMAKE_CURRENT_LIST_DIR}/../../../cmake/RenderFixtureList.cmake)
render_fixture_list(2 "penalty_view|--scenario ${SCENARIO_DIR}/penalty_view.yaml")
