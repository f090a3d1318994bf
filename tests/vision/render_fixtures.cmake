# Renders the vision accuracy fixtures once per build tree (cmake -P; CTest FIXTURES_SETUP).
#   -DRENDER=<houghloc-render> -DOUT=<folder> -DSCENARIO_DIR=<tests/vision/data>
# A folder with a .complete stamp is reused. Seeds differ from the ones the pipeline was tuned on.
set(fixtures
  "spl_nao-top_walk|--standard spl --camera nao-top --trajectory walk --seed 101"
  "spl_nao-bottom_random|--standard spl --camera nao-bottom --trajectory random-poses --seed 102"
  "kid_kid-wide_walk|--standard kid --camera kid-wide --trajectory walk --seed 103"
  "adult_adult_walk|--standard adult --camera adult --trajectory walk --seed 104"
  "msl_adult_random|--standard msl --camera adult --trajectory random-poses --seed 105"
  "spl2019_nao-top_random|--standard spl2019 --camera nao-top --trajectory random-poses --seed 106"
  "spl_nao-top_pose-error|--scenario ${SCENARIO_DIR}/pose_error.yaml --seed 107"
  "spl_nao-top_exact|--standard spl --camera nao-top --trajectory walk --seed 107")
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/RenderFixtureList.cmake)
render_fixture_list(40 ${fixtures})
