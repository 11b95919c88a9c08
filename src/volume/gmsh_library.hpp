// Gmsh's C API, loaded when first needed (dlopen): linking libgmsh would load its ~90 libraries
// (FLTK, X11, OpenGL, OCCT's data exchange) into every program that uses towgeom, 48 MB and
// 60 ms at start-up, though only meshVolumes() needs it.
#pragma once

#include <gmshc.h>

#include <cstddef>
#include <string>
#include <vector>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The Gmsh functions towgeom calls, resolved from the shared library. Each call checks Gmsh's
/// error flag and throws a string with Gmsh's last error message.
struct GmshApi {
#define TOWGEOM_GMSH_FUNCTION(name) decltype(&::name) name = nullptr;
    TOWGEOM_GMSH_FUNCTION(gmshInitialize)
    TOWGEOM_GMSH_FUNCTION(gmshFinalize)
    TOWGEOM_GMSH_FUNCTION(gmshFree)
    TOWGEOM_GMSH_FUNCTION(gmshOptionSetNumber)
    TOWGEOM_GMSH_FUNCTION(gmshOptionGetNumber)
    TOWGEOM_GMSH_FUNCTION(gmshModelAdd)
    TOWGEOM_GMSH_FUNCTION(gmshModelSetCurrent)
    TOWGEOM_GMSH_FUNCTION(gmshModelGetCurrent)
    TOWGEOM_GMSH_FUNCTION(gmshModelRemove)
    TOWGEOM_GMSH_FUNCTION(gmshModelAddDiscreteEntity)
    TOWGEOM_GMSH_FUNCTION(gmshModelMeshAddNodes)
    TOWGEOM_GMSH_FUNCTION(gmshModelMeshAddElementsByType)
    TOWGEOM_GMSH_FUNCTION(gmshModelGeoAddSurfaceLoop)
    TOWGEOM_GMSH_FUNCTION(gmshModelGeoAddVolume)
    TOWGEOM_GMSH_FUNCTION(gmshModelGeoSynchronize)
    TOWGEOM_GMSH_FUNCTION(gmshModelMeshGenerate)
    TOWGEOM_GMSH_FUNCTION(gmshModelMeshGetNodes)
    TOWGEOM_GMSH_FUNCTION(gmshModelMeshGetElementsByType)
    TOWGEOM_GMSH_FUNCTION(gmshLoggerGetLastError)
#undef TOWGEOM_GMSH_FUNCTION
};

/// The loaded library (loaded once; never unloaded). @throws towgeom::Error (EngineUnavailable)
/// naming the library and its Debian package when it cannot be loaded.
const GmshApi& gmshApi();

/// Gmsh's last error message ("no message" when it has none).
std::string gmshLastError(const GmshApi& api);

/// Throws std::runtime_error with Gmsh's last error if @p ierr is set.
void gmshCheck(const GmshApi& api, int ierr, const char* call);

/// An array Gmsh allocated, copied and freed.
template <class T>
std::vector<T> gmshTake(const GmshApi& api, T* data, std::size_t n)
{
    std::vector<T> v(data, data + n);
    api.gmshFree(data);
    return v;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
