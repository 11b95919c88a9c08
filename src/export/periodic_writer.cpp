// Periodic boundary conditions of a periodic cell's volume mesh as Abaqus/CalculiX *EQUATION.
#include <algorithm>
#include <array>
#include <map>
#include <ostream>
#include <vector>

#include "export/cell_face_triangles.hpp"
#include "export/edge_middles.hpp"
#include "export/number_writer.hpp"
#include "export/volume_mesh_checks.hpp"
#include "io/output_files.hpp"
#include "towgeom/error.hpp"
#include "towgeom/mesh_export.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

void writeAbaqusPeriodic(const TextileMesh& mesh, const VolumeMesh& volumes, std::ostream& out)
{
    if (!mesh.cell || !mesh.cell->box.periodic)
        throw Error(ErrorCode::InvalidArgument, "periodic boundary conditions need a mesh clipped to a periodic cell");
    detail::checkVolumeMeshOf(mesh, volumes);
    const CellMesh& cell = *mesh.cell;
    // The node pairs per axis, with quadratic tetrahedra's middle nodes: the middle of a min-face
    // edge pairs with the middle of its partners' edge.
    const detail::EdgeMiddles middles(volumes);
    std::array<std::vector<std::pair<std::size_t, std::size_t>>, 3> pairs = cell.periodicPairs;
    std::array<std::vector<std::size_t>, 6> onFace;
    std::array<std::vector<std::array<std::size_t, 3>>, 6> faceTriangles;
    for (std::size_t f = 0; f < 6; ++f) {
        faceTriangles[f] = detail::cellFaceTriangles(mesh, static_cast<CellFace>(f));
        onFace[f] = middles.withMiddles(cell.faceNodes[f], faceTriangles[f]);
    }
    if (!middles.empty())
        for (std::size_t a = 0; a < 3; ++a) {
            const std::map<std::size_t, std::size_t> partner(cell.periodicPairs[a].begin(), cell.periodicPairs[a].end());
            for (const auto& t : faceTriangles[2 * a])  // the min face's edges and their partners
                for (int e = 0; e < 3; ++e) {
                    const std::size_t u = t[static_cast<std::size_t>(e)], w = t[static_cast<std::size_t>((e + 1) % 3)];
                    const std::size_t* mid = middles.of(u, w);
                    const auto p = partner.find(u), q = partner.find(w);
                    if (!mid || p == partner.end() || q == partner.end())
                        throw Error(ErrorCode::InvalidArgument, "a min-face edge has no middle node or no partner on the max face");
                    const std::size_t* moved = middles.of(p->second, q->second);
                    if (!moved) throw Error(ErrorCode::InvalidArgument, "a min-face edge's partner edge is no edge of the tetrahedra");
                    pairs[a].emplace_back(*mid, *moved);
                }
            std::sort(pairs[a].begin(), pairs[a].end());
            pairs[a].erase(std::unique(pairs[a].begin(), pairs[a].end()), pairs[a].end());
        }
    // Per node, the highest axis on whose max face it lies (-1: none).
    std::vector<int> maxAxis(volumes.nodes.size(), -1);
    for (int a = 0; a < 3; ++a)
        for (std::size_t n : onFace[static_cast<std::size_t>(2 * a + 1)]) {
            if (n >= maxAxis.size()) throw Error(ErrorCode::InvalidArgument, "a cell face's node is not in the volume mesh");
            maxAxis[n] = a;
        }
    const std::size_t ref = volumes.nodes.size();  // REF_X, REF_Y, REF_Z: ref + 1 .. ref + 3 (1-based)
    detail::NumberWriter w(out);
    w.text("** towgeom: periodic boundary conditions of the cell (include after the mesh)").end();
    w.text("*NODE").end();
    const Point3& lo = cell.box.min;
    for (std::size_t k = 1; k <= 3; ++k) w.number(ref + k).text(", ").fitted(lo.x, 20).text(", ").fitted(lo.y, 20).text(", ").fitted(lo.z, 20).end();
    const char* names[3] = {"REF_X", "REF_Y", "REF_Z"};
    for (std::size_t k = 0; k < 3; ++k) w.text("*NSET, NSET=").text(names[k]).end().number(ref + k + 1).end();
    // The min corner: on all three min faces.
    std::vector<std::size_t> corner;
    for (std::size_t n : cell.faceNodes[0])
        if (std::binary_search(cell.faceNodes[2].begin(), cell.faceNodes[2].end(), n) &&
            std::binary_search(cell.faceNodes[4].begin(), cell.faceNodes[4].end(), n))
            corner.push_back(n);
    if (corner.size() != 1) throw Error(ErrorCode::Internal, "the cell's min corner is not one node");
    w.text("*NSET, NSET=CORNER").end().number(corner[0] + 1).end();
    // Highest axis first: a node made dependent by an axis's ties is never used again by a later
    // tie (Abaqus' rule for *EQUATION); the lower axes' ties use it only before, as independent.
    for (int a = 2; a >= 0; --a)
        for (const auto& [p, q] : pairs[static_cast<std::size_t>(a)]) {
            if (q >= maxAxis.size() || p >= maxAxis.size()) throw Error(ErrorCode::InvalidArgument, "a periodic pair's node is not in the volume mesh");
            if (maxAxis[q] != a) continue;  // tied by a higher axis
            for (int dof = 1; dof <= 3; ++dof) {
                w.text("*EQUATION").end().text("3").end();
                w.number(q + 1).text(", ").number(dof).text(", 1., ").number(p + 1).text(", ").number(dof).text(", -1., ");
                w.number(ref + static_cast<std::size_t>(a) + 1).text(", ").number(dof).text(", -1.").end();
            }
        }
    w.flush();
}

void writeAbaqusPeriodic(const TextileMesh& mesh, const VolumeMesh& volumes, const std::string& path)
{
    detail::OutputFiles files;
    writeAbaqusPeriodic(mesh, volumes, files.open(path));
    files.commit();
}

TOWGEOM_END_NAMESPACE
