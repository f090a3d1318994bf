# render_fixture_list(FRAMES "name|houghloc-render arguments" ...): for cmake -P fixture scripts
# (CTest FIXTURES_SETUP). Renders each fixture folder into ${OUT}/<name> with ${RENDER}, once per
# build tree: a folder with a .complete stamp is reused.
function(render_fixture_list frames)
  foreach(fixture ${ARGN})
    string(REPLACE "|" ";" parts "${fixture}")
    list(GET parts 0 name)
    list(GET parts 1 args)
    separate_arguments(args UNIX_COMMAND "${args}")
    if(NOT EXISTS ${OUT}/${name}/.complete)
      file(REMOVE_RECURSE ${OUT}/${name})
      execute_process(COMMAND ${RENDER} ${args} --frames ${frames} -q -o ${OUT}/${name}
                      RESULT_VARIABLE result)
      if(NOT result EQUAL 0)
        message(FATAL_ERROR "rendering ${name} failed (${result})")
      endif()
      file(TOUCH ${OUT}/${name}/.complete)
    endif()
  endforeach()
endfunction()
