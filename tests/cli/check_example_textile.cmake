# The bundled example textile must be exactly what its documented generator command produces.
file(REMOVE_RECURSE "${WORK}")
execute_process(
  COMMAND "${CLI}" generate --weave twill --repeat 2/2 --tows 4x4 --overlap 0.08 --sections 61 --points 24
          --out "${WORK}" --quiet
  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "generate failed (${status}): ${err}")
endif()
file(GLOB bundled RELATIVE "${BUNDLED}" "${BUNDLED}/*")
file(GLOB fresh RELATIVE "${WORK}" "${WORK}/*")
list(SORT bundled)
list(SORT fresh)
if(NOT bundled STREQUAL fresh)
  message(FATAL_ERROR "files differ: bundled ${bundled}, generated ${fresh}")
endif()
foreach(f IN LISTS bundled)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${BUNDLED}/${f}" "${WORK}/${f}" RESULT_VARIABLE differ)
  if(differ)
    message(FATAL_ERROR "${f} differs from the generator's output: regenerate examples/data/twill (see its README)")
  endif()
endforeach()
