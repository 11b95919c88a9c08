# Installs the built towgeom into a fresh prefix, then configures, builds and runs the consumer
# project (examples/consumer) against it with find_package(towgeom): the install tree must be
# self-sufficient (headers, library, towgeomConfig.cmake, towgeomConfigVersion.cmake).
file(REMOVE_RECURSE "${WORK}")
function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGV}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK}/prefix")
foreach(f include/towgeom/towgeom.hpp include/towgeom/version.hpp bin/towgeom)
  if(NOT EXISTS "${WORK}/prefix/${f}")
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
run(${CMAKE_COMMAND} -S "${CONSUMER_SOURCE}" -B "${WORK}/build" -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${WORK}/prefix")
run(${CMAKE_COMMAND} --build "${WORK}/build")
run("${WORK}/build/fit_volume" "${EXAMPLE}")
# The consumer prints "NAME VOLUME" (10 digits); the bundled straight tube (r = 0.5, L = 4, 24
# points around) fits a surface whose section is the periodic cubic B-spline through the 24-gon,
# 1.3263e-5 below pi r^2 (tests/support/analytic_reference.hpp): 3.14155098644 (was: pi within
# 0.05 %).
string(REGEX MATCH "^straight_tube ([0-9.]+)" matched "${last_output}")
if(NOT matched)
  message(FATAL_ERROR "unexpected consumer output: ${last_output}")
endif()
set(volume "${CMAKE_MATCH_1}")
if(volume LESS 3.141550985 OR volume GREATER 3.141550988)
  message(FATAL_ERROR "consumer volume ${volume} is not 3.14155098644 (the fitted B-spline tube's)")
endif()
run("${WORK}/prefix/bin/towgeom" --version)
message(STATUS "consumer: ${last_output}")
