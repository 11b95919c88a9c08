# Install rules and the CMake package (towgeomConfig.cmake, towgeomConfigVersion.cmake).
include(CMakePackageConfigHelpers)

set(TOWGEOM_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/towgeom")

set(towgeom_installed towgeom)
if(TOWGEOM_BUILD_CLI)
  list(APPEND towgeom_installed towgeom_cli)
endif()
install(TARGETS ${towgeom_installed} EXPORT towgeomTargets
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY include/towgeom DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES "${PROJECT_BINARY_DIR}/include/towgeom/version.hpp" "${PROJECT_BINARY_DIR}/include/towgeom/export.hpp" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/towgeom)
install(EXPORT towgeomTargets NAMESPACE towgeom:: DESTINATION ${TOWGEOM_CMAKE_DIR})

configure_package_config_file(cmake/towgeomConfig.cmake.in "${PROJECT_BINARY_DIR}/towgeomConfig.cmake"
  INSTALL_DESTINATION ${TOWGEOM_CMAKE_DIR})
write_basic_package_version_file("${PROJECT_BINARY_DIR}/towgeomConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/towgeomConfig.cmake" "${PROJECT_BINARY_DIR}/towgeomConfigVersion.cmake"
  DESTINATION ${TOWGEOM_CMAKE_DIR})
install(FILES LICENSE README.md CHANGELOG.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
# The libraries report.html inlines (Chart.js, three.js), which the binaries carry.
install(FILES src/report/assets/LICENSE.chart.js.md src/report/assets/LICENSE.kurkle-color.md src/report/assets/LICENSE.three.txt
  src/report/assets/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR}/report-assets)
