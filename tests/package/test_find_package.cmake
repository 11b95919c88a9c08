# Installs the built towgeom into a fresh prefix, then configures, builds and runs the consumer
# project (examples/consumer) against it with find_package(towgeom). For a shared libtowgeom
# (SHARED) the engines' CMake packages (OpenCASCADE, CGAL, Eigen3, nlohmann_json) cannot be
# found meanwhile: the install tree must be self-sufficient and towgeomConfig.cmake must not ask
# for them. A static one needs them for the link.
include("${CMAKE_CURRENT_LIST_DIR}/consumer_common.cmake")
file(REMOVE_RECURSE "${WORK}")
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK}/prefix")
foreach(f include/towgeom/towgeom.hpp include/towgeom/version.hpp include/towgeom/export.hpp bin/towgeom)
  if(NOT EXISTS "${WORK}/prefix/${f}")
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
set(no_engines "")
if(SHARED)
  set(no_engines -DCMAKE_DISABLE_FIND_PACKAGE_OpenCASCADE=ON -DCMAKE_DISABLE_FIND_PACKAGE_CGAL=ON
      -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON)
endif()
run(${CMAKE_COMMAND} -S "${CONSUMER_SOURCE}" -B "${WORK}/build" -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${WORK}/prefix" ${no_engines})
run(${CMAKE_COMMAND} --build "${WORK}/build")
check_consumer_volume("${WORK}/build/fit_volume" "${EXAMPLE}")

# One program per stage (examples/consumer), on the bundled data.
file(GLOB twill "${TWILL}/*.stw")
run("${WORK}/build/intersect_only" "${WORK}/loops.json" ${twill})
if(NOT last_output MATCHES "\n16 loops\n$")
  message(FATAL_ERROR "intersect_only: not the twill's 16 loops:\n${last_output}")
endif()
run("${WORK}/build/mesh_size_study" "${WORK}/loops.json" ${twill})
string(REGEX MATCHALL "16 regions" regions "${last_output}")
list(LENGTH regions sizes)
if(NOT sizes EQUAL 3)
  message(FATAL_ERROR "mesh_size_study: not 16 regions at each of 3 sizes:\n${last_output}")
endif()
message(STATUS "mesh_size_study:\n${last_output}")
run("${WORK}/build/rank_study" "${WORK}/loops.json" ${twill})
# Both rankings: 16 regions of the same overlap volume; each tow keeps all of its volume when it
# ranks first (warps, then wefts) and loses some when it gives way.
string(REGEX MATCHALL "first: 16 regions, overlap volume ([0-9.e-]+)" both "${last_output}")
list(LENGTH both rankings)
if(NOT rankings EQUAL 2 OR NOT last_output MATCHES "warp_0 keeps 100 %.*warp_0 keeps 9[0-9.]+ %")
  message(FATAL_ERROR "rank_study: not 16 regions under both rankings, or warp_0 not giving way second:\n${last_output}")
endif()
message(STATUS "rank_study:\n${last_output}")
run("${WORK}/build/mesh_one_tow" "${EXAMPLE}" "${WORK}/tube.vtk")
# The closed mesh's volume: within 0.5 % of the fitted tube's 3.14155.
if(NOT last_output MATCHES "volume (3\\.1[34][0-9]*)")
  message(FATAL_ERROR "mesh_one_tow: unexpected output ${last_output}")
endif()
message(STATUS "mesh_one_tow: ${last_output}")
run("${WORK}/prefix/bin/towgeom" --version)
