# 'docs': Doxygen over the public headers, every warning an error (undocumented members included).
find_package(Doxygen QUIET)
if(DOXYGEN_FOUND)
  set(TOWGEOM_DOXYFILE "${PROJECT_BINARY_DIR}/Doxyfile")
  configure_file("${CMAKE_CURRENT_LIST_DIR}/Doxyfile.in" "${TOWGEOM_DOXYFILE}" @ONLY)
  add_custom_target(docs
    COMMAND ${DOXYGEN_EXECUTABLE} "${TOWGEOM_DOXYFILE}"
    WORKING_DIRECTORY "${PROJECT_BINARY_DIR}"
    COMMENT "Doxygen: public API documentation (warnings are errors)"
    VERBATIM)
else()
  message(STATUS "Doxygen not found: no 'docs' target")
endif()
