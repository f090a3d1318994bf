# Renders the fault-injection recordings once per build tree (cmake -P; CTest FIXTURES_SETUP).
#   -DRENDER=<houghloc-render> -DOUT=<folder> -DSCENARIO_DIR=<tests/tools/faults>
# The clean run and one recording per fault: the same 10 s walk (seed 401), the fault from 4 s
# to 7 s (docs/reliability.md "Fault injection").
include(${CMAKE_CURRENT_LIST_DIR}/../../../cmake/RenderFixtureList.cmake)
set(fixtures)
foreach(name clean odometry_dropout robots_in_view motion_blur light_change camera_pose_delay
    odometry_scale camera_pitch_error frame_drop)
  list(APPEND fixtures "${name}|--scenario ${SCENARIO_DIR}/${name}.yaml")
endforeach()
render_fixture_list(300 ${fixtures})
