// The check every volume mesh passes before meshVolumes() returns it: its tetrahedra conform
// (every inner face shared by exactly two of them, every surface triangle a face of one
// tetrahedron per side it bounds, no other face on one only) and fill what they should (each
// tow's tetrahedra its surface's volume, a cell's all of the box).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "towgeom/volume_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// What the tetrahedra must match: the surface triangles given to the mesher, and the volumes.
struct ConformityTarget {
    /// Surface triangles that bound one volume (the outside of the whole mesh): each a face of
    /// exactly one tetrahedron.
    std::vector<std::array<std::size_t, 3>> outer;
    /// Surface triangles between two volumes (regions, a tow's surface in a cell's matrix): each
    /// a face of exactly two.
    std::vector<std::array<std::size_t, 3>> between;
    /// Per tow (VolumeMesh::tow's numbering, the matrix last if there is one): the volume its
    /// tetrahedra must add up to, and its name for messages.
    std::vector<double> volume;
    std::vector<std::string> name;
};

/// Throws Error (Internal) naming the place when @p mesh's tetrahedra do not conform to each
/// other and to @p target's surfaces (a face of more than two tetrahedra; an inner face of one
/// only: a crack; a surface triangle of the wrong number), or when a tow's tetrahedra differ
/// from its volume by more than 1e-9 of the largest. Runs on @p threads threads (0: one per
/// hardware thread).
void checkConformity(const VolumeMesh& mesh, const ConformityTarget& target, std::size_t threads = 1);

}  // namespace detail
TOWGEOM_END_NAMESPACE
