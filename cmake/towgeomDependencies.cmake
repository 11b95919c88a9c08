# The engines towgeom builds on; all from Debian 12 packages (see README.md).
# Shared between the build and the installed towgeomConfig.cmake (via find_dependency there).
# OCCT's version file accepts only an exact version, so the minimum is checked here.
find_package(OpenCASCADE REQUIRED CONFIG)
if(OpenCASCADE_VERSION VERSION_LESS 7.6)
  message(FATAL_ERROR "towgeom needs OpenCASCADE >= 7.6, found ${OpenCASCADE_VERSION}")
endif()
find_package(CGAL 5.5 REQUIRED CONFIG)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
# Header-only, used inside the library only (JSON reports): not needed by consumers.
find_package(nlohmann_json 3.11 REQUIRED CONFIG)

# The OCCT toolkits towgeom links (OCCT's imported targets carry no include directories).
set(TOWGEOM_OCCT_LIBRARIES TKernel TKMath TKG2d TKG3d TKGeomBase TKGeomAlgo
  # the trimmed B-rep (src/brep): topology, its checks and properties, STEP through XDE, and
  # booleans (TKBO, a box from TKPrim) to clip it to a cell
  TKBRep TKTopAlgo TKSTEP TKXDESTEP TKXSBase TKXCAF TKLCAF TKCAF TKBO TKPrim
  # fibre placement: the tool surface from STEP or IGES
  TKIGES)

# Gmsh (libgmsh-dev) meshes the tows' volumes (src/volume): its C API header is needed to build;
# the library is loaded when first used (dlopen of libgmsh.so.4.8), not linked, so programs that
# never mesh volumes do not load its ~90 libraries.
find_path(TOWGEOM_GMSH_INCLUDE_DIR gmshc.h)
if(NOT TOWGEOM_GMSH_INCLUDE_DIR)
  message(FATAL_ERROR "towgeom needs Gmsh's C API header gmshc.h (Debian: apt-get install libgmsh-dev)")
endif()
