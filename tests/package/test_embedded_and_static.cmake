# towgeom inside a host's build, then as a static package:
#  1. examples/embed adds towgeom's source tree with add_subdirectory (compiled by EMBED_CXX
#     when given: clang) and builds the consumer (examples/consumer) against towgeom::towgeom.
#     The host sets no build type and no BUILD_SHARED_LIBS: towgeom must set neither, build a
#     static library, no tests, no CLI.
#  2. The host's build installed (TOWGEOM_INSTALL=ON) gives a static towgeom package; the same
#     consumer is built against it with find_package(towgeom), which must find OpenCASCADE and
#     CGAL for the link.
include("${CMAKE_CURRENT_LIST_DIR}/consumer_common.cmake")
file(REMOVE_RECURSE "${WORK}")
set(host_compiler "")
if(EMBED_CXX)
  set(host_compiler "-DCMAKE_CXX_COMPILER=${EMBED_CXX}")
endif()
run(${CMAKE_COMMAND} -S "${EMBED_SOURCE}" -B "${WORK}/host" -G "${GENERATOR}" "-DTOWGEOM_SOURCE_DIR=${SOURCE_DIR}"
    -DTOWGEOM_INSTALL=ON -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE ${host_compiler})
file(STRINGS "${WORK}/host/CMakeCache.txt" build_type REGEX "^CMAKE_BUILD_TYPE:")
if(NOT build_type STREQUAL "CMAKE_BUILD_TYPE:STRING=")
  message(FATAL_ERROR "towgeom changed the host's build type: ${build_type}")
endif()
file(STRINGS "${WORK}/host/CMakeCache.txt" shared REGEX "^BUILD_SHARED_LIBS:")
if(shared)
  message(FATAL_ERROR "towgeom set BUILD_SHARED_LIBS for the host: ${shared}")
endif()
if(EXISTS "${WORK}/host/towgeom/tests" OR EXISTS "${WORK}/host/towgeom/benchmarks")
  message(FATAL_ERROR "towgeom added its tests or benchmarks to the host's build")
endif()
run(${CMAKE_COMMAND} --build "${WORK}/host" -j ${JOBS})
if(NOT EXISTS "${WORK}/host/towgeom/src/libtowgeom.a" OR EXISTS "${WORK}/host/towgeom/towgeom")
  message(FATAL_ERROR "inside a host towgeom must build a static library and no CLI")
endif()
check_consumer_volume("${WORK}/host/fit_volume" "${EXAMPLE}")

run(${CMAKE_COMMAND} --install "${WORK}/host" --prefix "${WORK}/prefix")
file(GLOB_RECURSE archives "${WORK}/prefix/*/libtowgeom.a")
if(NOT archives)
  message(FATAL_ERROR "the static package has no libtowgeom.a")
endif()
run(${CMAKE_COMMAND} -S "${CONSUMER_SOURCE}" -B "${WORK}/consumer" -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${WORK}/prefix")
run(${CMAKE_COMMAND} --build "${WORK}/consumer")
check_consumer_volume("${WORK}/consumer/fit_volume" "${EXAMPLE}")
