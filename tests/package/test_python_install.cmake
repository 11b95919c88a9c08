# The Python package as `cmake --install` installs it under a prefix (here a scratch one, as a
# user's --prefix): it imports from there alone, finds the installed libtowgeom through its
# relative RUNPATH, and fits the bundled straight tube to the volume the C++ consumers print
# (consumer_common.cmake).
#   -DBUILD_DIR=... -DPYTHON=... -DSITE=<package dir relative to the prefix> -DEXAMPLE=<straight_tube.stw> -DWORK=...
include("${CMAKE_CURRENT_LIST_DIR}/consumer_common.cmake")
file(REMOVE_RECURSE "${WORK}")
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK}/prefix")
set(ENV{PYTHONPATH} "${WORK}/prefix/${SITE}")
set(ENV{PYTHONDONTWRITEBYTECODE} 1)
run("${PYTHON}" -c "import towgeom
assert towgeom.__file__.startswith('${WORK}/prefix'), towgeom.__file__
tow = towgeom.TowSurface.fit(towgeom.read_stack('${EXAMPLE}'))
print(tow.name, repr(tow.volume()))")
string(REGEX MATCH "^straight_tube ([0-9.]+)" matched "${last_output}")
if(NOT matched OR CMAKE_MATCH_1 LESS 3.141550985 OR CMAKE_MATCH_1 GREATER 3.141550988)
  message(FATAL_ERROR "installed module: unexpected output '${last_output}' (the fitted tube's volume is 3.14155098644)")
endif()
message(STATUS "installed module: ${last_output}")
