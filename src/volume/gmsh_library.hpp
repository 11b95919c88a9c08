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

/// Every Gmsh function towgeom calls, as X(name): the one list both the table and the loader use.
#define TOWGEOM_GMSH_FUNCTIONS(X) \
    X(gmshInitialize) \
    X(gmshFinalize) \
    X(gmshFree) \
    X(gmshOptionSetNumber) \
    X(gmshOptionGetNumber) \
    X(gmshModelAdd) \
    X(gmshModelSetCurrent) \
    X(gmshModelGetCurrent) \
    X(gmshModelRemove) \
    X(gmshModelAddDiscreteEntity) \
    X(gmshModelMeshAddNodes) \
    X(gmshModelMeshAddElementsByType) \
    X(gmshModelGeoAddSurfaceLoop) \
    X(gmshModelGeoAddVolume) \
    X(gmshModelGeoSynchronize) \
    X(gmshModelMeshGenerate) \
    X(gmshModelMeshSetOrder) \
    X(gmshModelMeshGetNodes) \
    X(gmshModelMeshGetElementsByType) \
    X(gmshModelMeshSetSizeCallback) \
    X(gmshModelMeshRemoveSizeCallback) \
    X(gmshModelMeshOptimize) \
    X(gmshLoggerGetLastError)

/// The Gmsh functions towgeom calls, resolved from the shared library. Each call checks Gmsh's
/// error flag and throws a string with Gmsh's last error message.
struct GmshApi {
#define TOWGEOM_GMSH_FUNCTION(name) decltype(&::name) name = nullptr;
    TOWGEOM_GMSH_FUNCTIONS(TOWGEOM_GMSH_FUNCTION)
#undef TOWGEOM_GMSH_FUNCTION
};

/// The loaded library (loaded once; never unloaded). @throws towgeom::Error (EngineUnavailable)
/// naming the library and its Debian package when it cannot be loaded.
const GmshApi& gmshApi();

/// Gmsh's last error message ("no message" when it has none).
std::string gmshLastError(const GmshApi& api);
/// Gmsh's last error message as it is: empty when none was logged since Gmsh last cleared it
/// (its mesh generation clears it when it starts).
std::string gmshLastErrorText(const GmshApi& api);

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
