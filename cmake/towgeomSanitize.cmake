# Sanitizer and fuzzer builds: include this before any target is made.
#
#   TOWGEOM_SANITIZE=address,undefined   ASan + UBSan (any -fsanitize= list); every UBSan report
#                                        halts the program (-fno-sanitize-recover=all). Tests
#                                        labelled 'skip-sanitize' are not meant for this build.
#   TOWGEOM_BUILD_FUZZERS=ON             clang only: the library's objects are instrumented for
#                                        libFuzzer (-fsanitize=fuzzer-no-link: coverage counters
#                                        and comparison hooks, no-ops outside a fuzzer) and
#                                        tests/fuzz is built. With TOWGEOM_SANITIZE the same build
#                                        runs the tests under the sanitizers and fuzzes
#                                        (tests/build_sanitized.sh): the library is compiled once
#                                        for both.
#
# OpenCASCADE, CGAL's compiled parts and the C++ runtime come from Debian and are not
# instrumented; ASan still sees every allocation they make through malloc/new.
set(TOWGEOM_SANITIZE "" CACHE STRING "Sanitizers for every target, e.g. address,undefined (empty: none)")
option(TOWGEOM_BUILD_FUZZERS "Build the libFuzzer targets of tests/fuzz (clang only)" OFF)

if(TOWGEOM_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "TOWGEOM_BUILD_FUZZERS needs clang (libFuzzer), not ${CMAKE_CXX_COMPILER_ID}: "
                        "configure with -DCMAKE_CXX_COMPILER=clang++ (see tests/fuzz/run_fuzzers.sh)")
  endif()
  if(NOT TOWGEOM_SANITIZE)
    set(TOWGEOM_SANITIZE "address,undefined" CACHE STRING "" FORCE)
  endif()
endif()

# TOWGEOM_SANITIZE_OPTIONS: the compile options that instrument code, given to towgeom's own code
# (src/CMakeLists.txt: the library and the CLI; tests/fuzz: the fuzz harnesses). The tests'
# and benchmarks' code (Catch2, the CGAL and OCCT oracles, tests/support) is not instrumented:
# the sanitizers watch the code under test, and the oracles, which run in the Release tests as
# well, made up much of the sanitized tests' time uninstrumented code avoids. Every program and
# shared library is linked with the sanitizers' runtime (add_link_options), so the library's
# checks run whoever calls it.
set(TOWGEOM_SANITIZE_OPTIONS "")
if(TOWGEOM_SANITIZE)
  message(STATUS "towgeom: library, CLI and fuzz harnesses built with -fsanitize=${TOWGEOM_SANITIZE}")
  set(TOWGEOM_SANITIZE_OPTIONS -fsanitize=${TOWGEOM_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${TOWGEOM_SANITIZE} -fno-sanitize-recover=all)
endif()
# The instrumentation for libFuzzer, given to the library's objects (src/CMakeLists.txt): the
# code a fuzzer explores. Tests and benchmarks in the same build are not instrumented.
set(TOWGEOM_FUZZ_INSTRUMENTATION "")
if(TOWGEOM_BUILD_FUZZERS)
  set(TOWGEOM_FUZZ_INSTRUMENTATION -fsanitize=fuzzer-no-link)
endif()

# Every test runs with these options (ctest reads this file before it starts any test, and the
# tests' child processes, e.g. the CLI run by a test, inherit them); options already in the
# environment come last and win. A sanitizer report exits with status 86, which no test
# expects (the CLI's own codes are 0, 1 and 2), so a report can never pass for an expected
# failure. LeakSanitizer is on (ASan's default on Linux), stated so that it stays on.
# LeakSanitizer suppresses OpenCASCADE's process-lifetime statics of STEP, IGES and XCAF by their
# toolkits, and Gmsh HXT's leaks when its boundary recovery fails, by HXT's functions
# (tests/sanitizer/lsan_libraries.supp says why, and what that costs); nothing else is
# suppressed (OCCT allocates
# through malloc/free, so ASan sees no new/free mismatch).
if(TOWGEOM_SANITIZE)
  set(asan "exitcode=86:detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1")
  set(ubsan "exitcode=86:halt_on_error=1:print_stacktrace=1")
  file(WRITE "${PROJECT_BINARY_DIR}/sanitizer_environment.cmake"
    "set(ENV{ASAN_OPTIONS} \"${asan}:\$ENV{ASAN_OPTIONS}\")\n"
    "set(ENV{UBSAN_OPTIONS} \"${ubsan}:\$ENV{UBSAN_OPTIONS}\")\n"
    "set(ENV{LSAN_OPTIONS} \"suppressions=${PROJECT_SOURCE_DIR}/tests/sanitizer/lsan_libraries.supp:print_suppressions=0:\$ENV{LSAN_OPTIONS}\")\n")
  set_property(DIRECTORY "${PROJECT_SOURCE_DIR}" APPEND PROPERTY TEST_INCLUDE_FILES
    "${PROJECT_BINARY_DIR}/sanitizer_environment.cmake")
endif()
