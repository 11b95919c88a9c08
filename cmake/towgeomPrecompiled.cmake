# Precompiled headers: the engines' and the standard library's headers most sources include,
# parsed once per target instead of once per source (CMake's target_precompile_headers).
# They change no code: a source still includes what it uses, and builds the same without them
# (-DTOWGEOM_PRECOMPILE_HEADERS=OFF, e.g. to check that its includes are complete).
# On by default with clang only. Measured on the 2-core machine (2026-12-05): clang's PCH of the
# library's list is 120 MB, read lazily, and cell_faces.cpp under ASan compiles in 64 s with it
# against 86 s without; g++ 12 reads its 480 MB PCH whole for every source, so small sources
# went from 0.1 s to 9 s and the Release build took longer with it than without.
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  set(towgeom_pch_default ON)
else()
  set(towgeom_pch_default OFF)
endif()
option(TOWGEOM_PRECOMPILE_HEADERS "Precompile the engines' common headers for each target" ${towgeom_pch_default})

# The library's sources: CGAL's inexact kernel and 2D polygons, Eigen, nlohmann-json,
# OpenCASCADE's geometry basics and the standard headers most of them include.
set(TOWGEOM_PCH_LIBRARY
  <algorithm> <array> <cmath> <cstddef> <cstdint> <filesystem> <functional> <limits> <map>
  <memory> <mutex> <optional> <set> <sstream> <string> <utility> <vector>
  # CGAL before OpenCASCADE: OCCT's macro Handle(Class) would rewrite CGAL::Handle.
  <CGAL/Exact_predicates_inexact_constructions_kernel.h> <CGAL/Polygon_2_algorithms.h>
  <Eigen/Dense> <nlohmann/json.hpp>
  <Standard_Failure.hxx> <Geom_BSplineSurface.hxx> <GeomAdaptor_Surface.hxx> <gp_Pnt.hxx> <gp_Vec.hxx>
  <TColStd_Array1OfReal.hxx> <TColgp_Array2OfPnt.hxx>)

# The tests' and benchmarks' sources: Catch2's single header (the largest part of each test
# source's parse), the standard headers and towgeom's public API.
set(TOWGEOM_PCH_TESTS
  <algorithm> <array> <cmath> <filesystem> <fstream> <map> <regex> <set> <sstream> <string> <vector>
  <catch2/catch.hpp> <towgeom/towgeom.hpp>)

# towgeom_precompile(TARGET LIST): TARGET's sources start from the precompiled headers LIST.
function(towgeom_precompile target)
  if(TOWGEOM_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()

# Unity builds (CMake's -DCMAKE_UNITY_BUILD=ON; tests/run_tests.sh builds so): the library's and
# the CLI's sources are compiled eight to a translation unit, so each engine header is parsed once
# per batch. Measured on the 2-core machine (2026-12-07): the library's Release objects took 379 s
# of compile time against 632 s one by one, and clang's unoptimised library (the add_subdirectory
# test) 53 s of wall time against 87 s. The library's batches of eight, in the order of
# src/CMakeLists.txt, share no file-local name; larger batches would not compile yet (kPi,
# msSince, sideOf, ... are defined in several files), so the batch size is fixed at eight whatever
# a host sets. tests/, tests/support/, the fuzz harnesses and benchmarks/ set CMAKE_UNITY_BUILD OFF
# for their directories (the tests' sources define the same file-local helpers again and again).
# towgeom_unity_safe(TARGET): TARGET batches eight sources, each batch starting with CGAL's kernel,
# before any source's OpenCASCADE header defines the macro Handle(Class) that would rewrite CGAL's
# Handle (one by one, each source includes CGAL first; the precompiled headers do too).
function(towgeom_unity_safe target)
  set_target_properties(${target} PROPERTIES UNITY_BUILD_BATCH_SIZE 8
    UNITY_BUILD_CODE_BEFORE_INCLUDE "#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>")
endfunction()
