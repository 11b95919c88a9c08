// The triangles on one face of a cell's box: the matrix's and the tows' caps there.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "towgeom/textile_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Every triangle of @p mesh on face @p face of its cell (none without a cell): the matrix's, and
/// the tows' caps there (parametric: TowMesh::cutAt; mesh cut: TowFace::Cell on the face's plane).
inline std::vector<std::array<std::size_t, 3>> cellFaceTriangles(const TextileMesh& mesh, CellFace face)
{
    std::vector<std::array<std::size_t, 3>> out;
    if (!mesh.cell) return out;
    // A CellCut::Mesh cap (TowFace::Cell) is on the face whose plane holds its three nodes.
    const int axis = static_cast<int>(face) / 2;
    const double at = mesh.cell->box.plane(face);
    const auto onFace = [&](const std::array<std::size_t, 3>& t) {
        for (std::size_t n : t)
            if ((axis == 0 ? mesh.nodes[n].x : axis == 1 ? mesh.nodes[n].y : mesh.nodes[n].z) != at) return false;
        return true;
    };
    for (std::size_t k = 0; k < mesh.cell->triangles.size() && k < mesh.cell->face.size(); ++k)
        if (mesh.cell->face[k] == face) out.push_back(mesh.cell->triangles[k]);
    for (const TowMesh& m : mesh.tows)
        for (std::size_t k = 0; k < m.triangles.size() && k < m.face.size(); ++k) {
            const std::size_t end = m.face[k] == TowFace::Start ? 0 : m.face[k] == TowFace::End ? 1 : 2;
            if (end < 2 && m.cutAt[end] == face) out.push_back(m.triangles[k]);
            if (m.face[k] == TowFace::Cell && onFace(m.triangles[k])) out.push_back(m.triangles[k]);
        }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
