# Renders the rendered hint matrix's walks once per build tree (cmake -P; CTest FIXTURES_SETUP).
#   -DRENDER=<houghloc-render> -DFIELDMAP=<houghloc-fieldmap> -DOUT=<folder> -DDATA=<data folder>
# 90 frames (3 s) each: the base walk (spl, nao-top, 0.65 m from the centre mark), one walk per
# other start place, view and field, and the base walk with an unannounced kidnap at 2.5 s.
if(NOT EXISTS ${OUT}/small_field.yaml)
  file(MAKE_DIRECTORY ${OUT})
  execute_process(COMMAND ${FIELDMAP} import-spl ${DATA}/small_spl_field_dimensions.json
                          -o ${OUT}/small_field.yaml RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "importing the small field failed (${result})")
  endif()
endif()
set(B "--scenario ${DATA}/hint_walk.yaml")
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/RenderFixtureList.cmake)
render_fixture_list(90
  "spl_nao-top_centre|${B} --standard spl --camera nao-top"
  "spl_nao-top_penalty|--scenario ${DATA}/hint_walk_penalty.yaml --standard spl --camera nao-top"
  "spl_nao-top_corner|--scenario ${DATA}/hint_walk_corner.yaml --standard spl --camera nao-top"
  "spl_kid-wide_centre|${B} --standard spl --camera kid-wide"
  "spl_wide-pinhole_centre|${B} --standard spl --camera wide-pinhole"
  "kid_nao-top_centre|${B} --standard kid --camera nao-top"
  "small_nao-top_centre|${B} --field ${OUT}/small_field.yaml --camera nao-top"
  "spl_nao-top_centre_kidnap|--scenario ${DATA}/hint_walk_kidnap.yaml --standard spl --camera nao-top")
