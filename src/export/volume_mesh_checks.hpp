// The writers' check that a volume mesh belongs to a surface mesh and names only what it has.
#pragma once

#include <string>

#include "towgeom/error.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/volume_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Throws Error (InvalidArgument) unless @p volumes is a volume mesh of @p mesh: @p mesh's nodes
/// first, one tow per tetrahedron naming a tow of @p mesh (or, with VolumeMesh::withMatrix, the
/// matrix: the tow count), every corner and middle node in range, middle nodes for all
/// tetrahedra or none, fibre directions one per tetrahedron or none.
inline void checkVolumeMeshOf(const TextileMesh& mesh, const VolumeMesh& volumes)
{
    const auto refuse = [](const std::string& what) { throw Error(ErrorCode::InvalidArgument, what); };
    if (volumes.surfaceNodes != mesh.nodes.size() || volumes.nodes.size() < mesh.nodes.size() ||
        volumes.tetrahedra.size() != volumes.tow.size())
        refuse("the volume mesh is not one of this surface mesh (meshVolumes() of it)");
    if (!volumes.edgeNodes.empty() && volumes.edgeNodes.size() != volumes.tetrahedra.size())
        refuse("the volume mesh has middle nodes for some of its tetrahedra only");
    if (!volumes.fibreDirection.empty() && volumes.fibreDirection.size() != volumes.tetrahedra.size())
        refuse("the volume mesh has " + std::to_string(volumes.fibreDirection.size()) + " fibre directions for " +
               std::to_string(volumes.tetrahedra.size()) + " tetrahedra");
    const std::size_t towCount = mesh.tows.size();
    for (std::size_t t : volumes.tow)
        if (t > towCount || (t == towCount && !volumes.withMatrix)) refuse("a tetrahedron names a tow out of range");
    for (const auto& t : volumes.tetrahedra)
        for (std::size_t n : t)
            if (n >= volumes.nodes.size()) refuse("a tetrahedron names a node out of range");
    for (const auto& e : volumes.edgeNodes)
        for (std::size_t n : e)
            if (n >= volumes.nodes.size()) refuse("a tetrahedron names a middle node out of range");
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
