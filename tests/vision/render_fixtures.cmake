# Renders the vision accuracy fixtures once per build tree (cmake -P; CTest FIXTURES_SETUP).
#   -DRENDER=<houghloc-render> -DOUT=<folder> -DSCENARIO_DIR=<tests/vision/data>
# A folder with a .complete stamp is reused. Seeds differ from the ones the pipeline was tuned on.
# The accuracy fixtures (*_robots) have every realism option on (scenario defaults) plus 20 robots
# walking across the field (occluders_*.yaml). exact, exact_seed201 (the bench recording's seed,
# on which the corrector once went wrong) and pose-error serve the pitch/roll corrector's tests.
set(W "--scenario ${SCENARIO_DIR}/occluders_walk.yaml")
set(R "--scenario ${SCENARIO_DIR}/occluders_random.yaml")
set(fixtures
  "spl_nao-top_walk_robots|${W} --standard spl --camera nao-top --seed 101"
  "spl_nao-bottom_random_robots|${R} --standard spl --camera nao-bottom --seed 102"
  "kid_kid-wide_walk_robots|${W} --standard kid --camera kid-wide --seed 103"
  "adult_adult_walk_robots|${W} --standard adult --camera adult --seed 104"
  "msl_adult_random_robots|${R} --standard msl --camera adult --seed 105"
  "spl2019_nao-top_random_robots|${R} --standard spl2019 --camera nao-top --seed 106"
  "spl_nao-top_pose-error|--scenario ${SCENARIO_DIR}/pose_error.yaml --seed 107"
  "spl_nao-top_exact|--standard spl --camera nao-top --trajectory walk --seed 107"
  "spl_nao-top_exact_seed201|--standard spl --camera nao-top --trajectory walk --seed 201"
  # After what houghloc-frame-stats found the renders lack beside the real frames (docs/render.md):
  # a close, bright hall filling half the view; a dim teal carpet with greyish tape; dim,
  # bluish-magenta light before dark stands; a grey carpet.
  "spl_nao-top_hall_close|--scenario ${SCENARIO_DIR}/hall_close.yaml --standard spl --camera nao-top --seed 121"
  "spl_nao-top_teal_carpet|--scenario ${SCENARIO_DIR}/teal_carpet.yaml --standard spl --camera nao-top --seed 122"
  "spl_nao-top_dim_tinted|--scenario ${SCENARIO_DIR}/dim_tinted.yaml --standard spl --camera nao-top --seed 123"
  "spl_nao-top_grey_carpet|--scenario ${SCENARIO_DIR}/grey_carpet.yaml --standard spl --camera nao-top --seed 124")
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/RenderFixtureList.cmake)
render_fixture_list(40 ${fixtures})
# The pitch/roll corrector over 10 s of walking (the 40-frame walks above are mostly its first
# second): the robots walk of seed 101, the plain walk of seed 107, and walks on the msl and
# spl2019 fields (their random-pose fixtures give the localizer no track to feed back).
# spl_nao_walk_robots_300: a NAO's two cameras taking turns, as on the robot; its bottom camera
# sees the robot's own feet in a walking step.
render_fixture_list(300
  "spl_nao-top_walk_robots_300|${W} --standard spl --camera nao-top --seed 101"
  "spl_nao-top_walk_300|--standard spl --camera nao-top --trajectory walk --seed 107"
  "msl_adult_walk_robots_300|${W} --standard msl --camera adult --seed 108"
  "spl2019_nao-top_walk_robots_300|${W} --standard spl2019 --camera nao-top --seed 109"
  "spl_nao_walk_robots_300|${W} --standard spl --camera nao --seed 110")
# The first 4 s of a NAO walk on which the corrector once ran away to its 4 deg limit.
render_fixture_list(120 "spl_nao_walk_robots_120|${W} --standard spl --camera nao --seed 311")
