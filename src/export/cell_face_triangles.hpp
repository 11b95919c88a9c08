// The triangles on one face of a cell's box: the matrix's and the tows' caps there.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "towgeom/textile_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Every triangle of @p mesh on face @p face of its cell (none without a cell).
inline std::vector<std::array<std::size_t, 3>> cellFaceTriangles(const TextileMesh& mesh, CellFace face)
{
    std::vector<std::array<std::size_t, 3>> out;
    if (!mesh.cell) return out;
    for (std::size_t k = 0; k < mesh.cell->triangles.size() && k < mesh.cell->face.size(); ++k)
        if (mesh.cell->face[k] == face) out.push_back(mesh.cell->triangles[k]);
    for (const TowMesh& m : mesh.tows)
        for (std::size_t k = 0; k < m.triangles.size() && k < m.face.size(); ++k) {
            const std::size_t end = m.face[k] == TowFace::Start ? 0 : m.face[k] == TowFace::End ? 1 : 2;
            if (end < 2 && m.cutAt[end] == face) out.push_back(m.triangles[k]);
        }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
