# Runs `towgeom SUBCOMMAND GOOD... INPUT --out WORK/out --quiet` and checks that a bad input is
# refused properly: exit status 2, one stderr line "towgeom SUBCOMMAND: " naming the file (and
# line, when LINE > 0) and the error code, nothing on stdout, and no file left in the output
# directory, not even an empty one (GOOD alone would have written one).
#   SUBCOMMAND  default fit; GOOD  valid inputs given before INPUT, separated by '|'
if(NOT SUBCOMMAND)
  set(SUBCOMMAND fit)
endif()
string(REPLACE "|" ";" good "${GOOD}")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(
  COMMAND "${CLI}" ${SUBCOMMAND} ${good} "${INPUT}" --out "${WORK}/out" --quiet
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 2)
  message(FATAL_ERROR "expected exit status 2, got '${status}'\nstderr: ${err}")
endif()
if(NOT out STREQUAL "")
  message(FATAL_ERROR "expected nothing on stdout, got: ${out}")
endif()
string(REGEX MATCHALL "\n" newlines "${err}")
list(LENGTH newlines count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "expected exactly one line on stderr, got ${count}: ${err}")
endif()
if(LINE GREATER 0)
  set(where "towgeom ${SUBCOMMAND}: ${INPUT}:${LINE}: ")
else()
  set(where "towgeom ${SUBCOMMAND}: ${INPUT}: ")
endif()
string(FIND "${err}" "${where}" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "stderr does not start with '${where}': ${err}")
endif()
string(FIND "${err}" "[${CODE}]" at)
if(at EQUAL -1)
  message(FATAL_ERROR "stderr does not give the code [${CODE}]: ${err}")
endif()
# Directories too (GLOB_RECURSE lists only files by default): an empty WORK/out left behind is
# output too.
file(GLOB_RECURSE left LIST_DIRECTORIES true "${WORK}/*")
if(left)
  message(FATAL_ERROR "output left behind after an input error: ${left}")
endif()
message(STATUS "ok: ${err}")
