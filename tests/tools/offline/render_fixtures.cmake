# Renders the houghloc-offline accuracy fixtures once per build tree (cmake -P; CTest
# FIXTURES_SETUP).  -DRENDER=<houghloc-render> -DOUT=<folder>
# A folder with a .complete stamp is reused. Seeds 301, 302 were never used for tuning.
set(fixtures
  "spl_nao-top_walk|--standard spl --camera nao-top --trajectory walk --seed 301"
  "kid_kid-wide_walk|--standard kid --camera kid-wide --trajectory walk --seed 302")
foreach(fixture ${fixtures})
  string(REPLACE "|" ";" parts "${fixture}")
  list(GET parts 0 name)
  list(GET parts 1 args)
  separate_arguments(args UNIX_COMMAND "${args}")
  if(NOT EXISTS ${OUT}/${name}/.complete)
    file(REMOVE_RECURSE ${OUT}/${name})
    execute_process(COMMAND ${RENDER} ${args} --frames 200 -q -o ${OUT}/${name}
                    RESULT_VARIABLE result)
    if(NOT result EQUAL 0)
      message(FATAL_ERROR "rendering ${name} failed (${result})")
    endif()
    file(TOUCH ${OUT}/${name}/.complete)
  endif()
endforeach()
