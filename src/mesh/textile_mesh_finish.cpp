#include "mesh/textile_mesh_finish.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "mesh/mesh_measures.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using Triple = std::array<std::size_t, 3>;

/// @p t's nodes ascending: a triangle's key whichever way round it runs.
Triple sorted(Triple t)
{
    std::sort(t.begin(), t.end());
    return t;
}

/// Whether triangle @p k of tow @p t is the tow's own (not a region's copy in its secondary).
bool ownTriangle(const TextileMesh& mesh, std::size_t t, std::size_t k)
{
    const TowMesh& m = mesh.tows[t];
    return !(k < m.region.size() && m.region[k] >= 0 && mesh.regions[static_cast<std::size_t>(m.region[k])].secondary == t);
}

/// Drops the triangles of @p mesh's sharp corners that are not (or no longer) their tow's own
/// (given up to a region of a tow ranked above, beyond a cell's cut, or with a node no triangle
/// uses: SIZE_MAX), then the corners with none left.
void keepStandingCorners(TextileMesh& mesh)
{
    std::map<std::pair<std::size_t, Triple>, bool> standing;  // (tow, sorted triangle) -> still its own
    for (const SharpCorner& c : mesh.sharpCorners)
        for (const Triple& t : c.triangles) standing.emplace(std::make_pair(c.tow, sorted(t)), false);
    if (standing.empty()) return;
    for (std::size_t t = 0; t < mesh.tows.size(); ++t) {
        const TowMesh& m = mesh.tows[t];
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            if (!ownTriangle(mesh, t, k)) continue;
            const auto it = standing.find({t, sorted(m.triangles[k])});
            if (it != standing.end()) it->second = true;
        }
    }
    for (SharpCorner& c : mesh.sharpCorners) {
        auto& tris = c.triangles;
        tris.erase(std::remove_if(tris.begin(), tris.end(), [&](const Triple& t) { return !standing.at({c.tow, sorted(t)}); }), tris.end());
    }
    auto& corners = mesh.sharpCorners;
    corners.erase(std::remove_if(corners.begin(), corners.end(), [](const SharpCorner& c) { return c.triangles.empty() || c.node == SIZE_MAX; }),
                  corners.end());
}

}  // namespace

void keepUsedNodes(TextileMesh& mesh)
{
    std::vector<std::size_t> renumber(mesh.nodes.size(), SIZE_MAX);
    std::vector<Point3> kept;
    for (TowMesh& m : mesh.tows)
        for (std::array<std::size_t, 3>& tri : m.triangles)
            for (std::size_t& n : tri) {
                if (renumber[n] == SIZE_MAX) {
                    renumber[n] = kept.size();
                    kept.push_back(mesh.nodes[n]);
                }
                n = renumber[n];
            }
    if (mesh.cell)  // the box's nodes the tows do not use (its edges, the matrix's faces)
        for (std::array<std::size_t, 3>& tri : mesh.cell->triangles)
            for (std::size_t& n : tri) {
                if (renumber[n] == SIZE_MAX) {
                    renumber[n] = kept.size();
                    kept.push_back(mesh.nodes[n]);
                }
                n = renumber[n];
            }
    const auto used = [&](std::size_t n) { return renumber[n] != SIZE_MAX; };
    const auto renumbered = [&](std::vector<std::size_t>& list) {
        list.erase(std::remove_if(list.begin(), list.end(), [&](std::size_t n) { return !used(n); }), list.end());
        for (std::size_t& n : list) n = renumber[n];
    };
    for (TowMesh& m : mesh.tows) {
        auto& p = m.parameters;
        p.erase(std::remove_if(p.begin(), p.end(), [&](const auto& e) { return !used(e.first); }), p.end());
        for (auto& e : p) e.first = renumber[e.first];
        std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    }
    for (MeshedLoop& l : mesh.loops) renumbered(l.nodes);
    auto& corners = mesh.sharpCorners;
    for (SharpCorner& c : corners) {
        c.node = used(c.node) ? renumber[c.node] : SIZE_MAX;
        for (auto& t : c.triangles)
            for (std::size_t& n : t) n = used(n) ? renumber[n] : SIZE_MAX;
    }
    keepStandingCorners(mesh);
    for (ConnectedRegion& g : mesh.regions) {
        renumbered(g.nodes);
        renumbered(g.loopNodes);
        std::sort(g.nodes.begin(), g.nodes.end());
    }
    if (mesh.cell) {
        for (auto& list : mesh.cell->faceNodes) {
            renumbered(list);
            std::sort(list.begin(), list.end());
        }
        for (auto& pairs : mesh.cell->periodicPairs) {
            pairs.erase(std::remove_if(pairs.begin(), pairs.end(), [&](const auto& p) { return !used(p.first) || !used(p.second); }),
                        pairs.end());
            for (auto& p : pairs) p = {renumber[p.first], renumber[p.second]};
            std::sort(pairs.begin(), pairs.end());
        }
    }
    auto& triple = mesh.triplePoints;
    triple.erase(std::remove_if(triple.begin(), triple.end(), [&](const TriplePoint& p) { return !used(p.node); }), triple.end());
    for (TriplePoint& p : triple) p.node = renumber[p.node];
    mesh.nodes = std::move(kept);
}

void keepResolvedTriplePoints(TextileMesh& mesh, const std::vector<IntersectionLoop>& loops)
{
    if (mesh.triplePoints.empty()) return;
    // Per triple node: the tow pairs with a loop through it, and the tows whose meshes use it.
    std::map<std::size_t, std::set<std::pair<std::size_t, std::size_t>>> pairsAt;
    std::map<std::size_t, std::set<std::size_t>> towsAt;
    for (const TriplePoint& p : mesh.triplePoints) {
        pairsAt[p.node];
        towsAt[p.node];
    }
    for (const MeshedLoop& l : mesh.loops) {
        if (l.loop >= loops.size()) continue;
        for (std::size_t n : l.nodes)
            if (const auto it = pairsAt.find(n); it != pairsAt.end()) it->second.emplace(loops[l.loop].towA(), loops[l.loop].towB());
    }
    for (std::size_t t = 0; t < mesh.tows.size(); ++t)
        for (const std::array<std::size_t, 3>& tri : mesh.tows[t].triangles)
            for (std::size_t n : tri)
                if (const auto it = towsAt.find(n); it != towsAt.end()) it->second.insert(t);
    auto& triple = mesh.triplePoints;
    triple.erase(std::remove_if(triple.begin(), triple.end(),
                                [&](const TriplePoint& p) {
                                    const auto& pairs = pairsAt[p.node];
                                    const auto& at = towsAt[p.node];
                                    const auto [a, b, c] = p.tows;
                                    return !(pairs.count({a, b}) && pairs.count({a, c}) && pairs.count({b, c}) && at.count(a) &&
                                             at.count(b) && at.count(c));
                                }),
                 triple.end());
}

MeshQuality meshQuality(const TextileMesh& mesh, double angleBound)
{
    MeshQuality q;
    q.histogram.assign(12, 0);
    q.minAngle = q.minAngleAwayFromCorners = 180.0;
    q.angleBound = angleBound;
    // (tow, the triangle's nodes sorted) -> the sharpest corner it is in.
    std::map<std::pair<std::size_t, Triple>, double> corner;
    for (const SharpCorner& c : mesh.sharpCorners)
        for (const Triple& t : c.triangles) {
            auto [it, added] = corner.emplace(std::make_pair(c.tow, sorted(t)), c.angle);
            if (!added) it->second = std::min(it->second, c.angle);
        }
    for (std::size_t t = 0; t < mesh.tows.size(); ++t) {
        const TowMesh& m = mesh.tows[t];
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            if (!ownTriangle(mesh, t, k)) continue;  // counted once, in its primary
            const double a = smallestAngle(mesh.nodes, m.triangles[k]);
            q.minAngle = std::min(q.minAngle, a);
            ++q.histogram[std::min<std::size_t>(11, static_cast<std::size_t>(a / 5.0))];
            ++q.triangles;
            if (a < angleBound) {
                const auto it = corner.find({t, sorted(m.triangles[k])});
                if (it != corner.end() && a >= it->second / 3.0) {
                    ++q.atSharpCorners;
                    continue;
                }
                ++q.underBound;
            }
            q.minAngleAwayFromCorners = std::min(q.minAngleAwayFromCorners, a);
        }
    }
    return q;
}

}  // namespace detail

double MeshQuality::fractionAtLeast(double degrees) const
{
    if (triangles == 0) return 1.0;
    std::size_t below = 0;
    for (std::size_t b = 0; b < histogram.size(); ++b)
        if (5.0 * static_cast<double>(b + 1) <= degrees) below += histogram[b];
    return 1.0 - static_cast<double>(below) / static_cast<double>(triangles);
}

TOWGEOM_END_NAMESPACE
