#include "cell/mesh_clip.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <chrono>
#include <string>
#include <cstddef>
#include <limits>

#include "cell/box_caps.hpp"
#include "cell/cell_faces.hpp"
#include "cell/plane_clip.hpp"
#include "core/progress_report.hpp"
#include "mesh/mesh_measures.hpp"
#include "mesh/textile_mesh_finish.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

constexpr std::size_t kUnused = std::numeric_limits<std::size_t>::max();

/// Drops the nodes no triangle uses and renumbers the rest in their order; everything that names
/// a node follows (what names a node gone is dropped).
void dropUnusedNodes(TextileMesh& mesh, const NodeParameters& uv)
{
    std::vector<std::size_t> to(mesh.nodes.size(), kUnused);
    const auto use = [&](const std::vector<std::array<std::size_t, 3>>& triangles) {
        for (const auto& t : triangles)
            for (std::size_t n : t) to[n] = 0;
    };
    for (const TowMesh& m : mesh.tows) use(m.triangles);
    if (mesh.cell) use(mesh.cell->triangles);
    std::vector<Point3> nodes;
    for (std::size_t n = 0; n < to.size(); ++n)
        if (to[n] != kUnused) {
            to[n] = nodes.size();
            nodes.push_back(mesh.nodes[n]);
        }
    mesh.nodes = std::move(nodes);
    const auto renumber = [&](std::vector<std::size_t>& list) {
        std::vector<std::size_t> kept;
        for (std::size_t n : list)
            if (to[n] != kUnused) kept.push_back(to[n]);
        list = std::move(kept);
    };
    const auto renumberTriangles = [&](std::vector<std::array<std::size_t, 3>>& triangles) {
        std::vector<std::array<std::size_t, 3>> kept;
        for (auto t : triangles)
            if (to[t[0]] != kUnused && to[t[1]] != kUnused && to[t[2]] != kUnused) kept.push_back({to[t[0]], to[t[1]], to[t[2]]});
        triangles = std::move(kept);
    };
    for (std::size_t t = 0; t < mesh.tows.size(); ++t) {
        TowMesh& m = mesh.tows[t];
        renumberTriangles(m.triangles);
        m.parameters.clear();
        for (const auto& [n, w] : uv[t])
            if (to[n] != kUnused) m.parameters.emplace_back(to[n], w);
        std::sort(m.parameters.begin(), m.parameters.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        m.cutAt = {};
    }
    if (mesh.cell) {
        renumberTriangles(mesh.cell->triangles);
        for (auto& list : mesh.cell->faceNodes) renumber(list);
    }
    for (MeshedLoop& l : mesh.loops) renumber(l.nodes);
    std::vector<TriplePoint> triple;
    for (TriplePoint p : mesh.triplePoints)
        if (to[p.node] != kUnused) {
            p.node = to[p.node];
            triple.push_back(p);
        }
    mesh.triplePoints = std::move(triple);
    std::vector<SharpCorner> corners;
    for (SharpCorner c : mesh.sharpCorners)
        if (to[c.node] != kUnused) {
            c.node = to[c.node];
            renumberTriangles(c.triangles);
            if (!c.triangles.empty()) corners.push_back(std::move(c));
        }
    mesh.sharpCorners = std::move(corners);
    for (ConnectedRegion& r : mesh.regions) {
        renumber(r.nodes);
        renumber(r.loopNodes);
    }
}

/// Drops the regions left without triangles and renumbers the rest (TowMesh::region follows).
void dropEmptyRegions(TextileMesh& mesh)
{
    std::vector<long> to(mesh.regions.size(), -1);
    std::vector<ConnectedRegion> kept;
    for (std::size_t r = 0; r < mesh.regions.size(); ++r)
        if (!mesh.regions[r].triangles.empty()) {
            to[r] = static_cast<long>(kept.size());
            kept.push_back(std::move(mesh.regions[r]));
        }
    mesh.regions = std::move(kept);
    for (TowMesh& m : mesh.tows)
        for (long& r : m.region)
            if (r >= 0) r = to[static_cast<std::size_t>(r)];
}

}  // namespace

TextileMesh clipMeshToCell(TextileMesh mesh, const std::vector<TowSurface>& tows, const Cell& cell, double h, double minAngle)
{
    NodeParameters uv = nodeParameters(mesh);
    snapToCellPlanes(mesh, uv, tows, cell, kCellSnapFraction);
    std::vector<std::vector<std::array<std::size_t, 3>>> solids;
    for (const TowMesh& m : mesh.tows) solids.push_back(m.triangles);
    clipToCellPlanes(mesh, uv, tows, cell, kCellSnapFraction);
    mesh.cell = meshBoxCaps(mesh, solids, cell, h, minAngle);
    dropEmptyRegions(mesh);
    dropUnusedNodes(mesh, uv);
    return mesh;
}

ResolveResult clipResultToCell(const std::vector<TowSurface>& tows, ResolveResult result, const ResolveOptions& options)
{
    if (!options.cell) return result;
    detail::sayStage(options, "clipping the meshes to the cell");
    const auto t0 = std::chrono::steady_clock::now();
    double h = std::numeric_limits<double>::infinity();
    for (const TowResolution& r : result.tows)
        if (r.meshSize > 0.0) h = std::min(h, r.meshSize);
    if (!std::isfinite(h)) h = cellFaceSize(*options.cell, {});
    result.mesh = clipMeshToCell(std::move(result.mesh), tows, *options.cell, h, options.mesh.minAngle);
    for (std::size_t t = 0; t < result.mesh.tows.size() && t < result.tows.size(); ++t) {
        const auto& triangles = result.mesh.tows[t].triangles;
        const SurfaceFigures f = surfaceFigures(result.mesh.nodes, triangles);
        if (f.badEdges != 0 || f.boundaryLoops != 0)
            throw Error(ErrorCode::Internal, "tow '" + result.mesh.tows[t].name + "': not closed after clipping to the cell (" +
                                                 notClosedMessage(true, f.badEdges, f.boundaryLoops) + ")");
        TowResolution& r = result.tows[t];
        r.volumeAfter = f.volume;
        r.area = f.area;
        r.boundaryLoops = 0;
        r.pieces = connectedPieces(triangles);
    }
    const double bound = result.quality.angleBound;
    const std::size_t over = result.quality.facesOverBounds;
    result.quality = meshQuality(result.mesh, bound);
    result.quality.facesOverBounds = over;
    result.timings.regions += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return result;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
