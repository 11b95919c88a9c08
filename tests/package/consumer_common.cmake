# Shared by the package tests: run(COMMAND...) fails the test with the command's output, and
# check_consumer_volume(PROGRAM EXAMPLE) runs a built consumer (examples/consumer/fit_volume.cpp)
# on the bundled straight tube and checks the volume it prints: the fitted B-spline tube's,
# 3.14155098644 (r = 0.5, L = 4, 24 points around: its section is the periodic cubic B-spline
# through the 24-gon, 1.3263e-5 below pi r^2; tests/support/analytic_reference.hpp).
function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGV}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

function(check_consumer_volume program example)
  run("${program}" "${example}")
  string(REGEX MATCH "^straight_tube ([0-9.]+)" matched "${last_output}")
  if(NOT matched)
    message(FATAL_ERROR "unexpected consumer output: ${last_output}")
  endif()
  set(volume "${CMAKE_MATCH_1}")
  if(volume LESS 3.141550985 OR volume GREATER 3.141550988)
    message(FATAL_ERROR "consumer volume ${volume} is not 3.14155098644 (the fitted B-spline tube's)")
  endif()
  message(STATUS "consumer: ${last_output}")
endfunction()
