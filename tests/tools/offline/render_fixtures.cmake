# Renders the houghloc-offline accuracy fixtures once per build tree (cmake -P; CTest
# FIXTURES_SETUP).  -DRENDER=<houghloc-render> -DOUT=<folder>
# A folder with a .complete stamp is reused. Seeds 301-304 were never used for tuning.
set(fixtures
  "spl_nao-top_walk|--standard spl --camera nao-top --trajectory walk --seed 301"
  "kid_kid-wide_walk|--standard kid --camera kid-wide --trajectory walk --seed 302"
  "spl_kid-wide_walk|--standard spl --camera kid-wide --trajectory walk --seed 303"
  "kid_nao-top_walk|--standard kid --camera nao-top --trajectory walk --seed 304")
include(${CMAKE_CURRENT_LIST_DIR}/../../../cmake/RenderFixtureList.cmake)
render_fixture_list(200 ${fixtures})
# A NAO (both cameras) whose recorded camera poses are 2 / 1 deg off (pitch / roll corrector,
# shared between the cameras); seed 311's first segments once sent the corrector to 4 deg.
render_fixture_list(150
  "spl_nao_walk_pose-error|--scenario ${CMAKE_CURRENT_LIST_DIR}/data/nao_pose_error.yaml --standard spl --camera nao --seed 311")
