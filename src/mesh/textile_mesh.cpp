#include "towgeom/textile_mesh.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace towgeom {

namespace {

using Edge = std::pair<std::size_t, std::size_t>;

/// Directed boundary edges (used by one triangle only), as (from, to) in triangle order.
std::vector<Edge> boundaryEdges(const TowMesh& m)
{
    std::map<Edge, int> count;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::size_t a = t[k], b = t[(k + 1) % 3];
            ++count[{std::min(a, b), std::max(a, b)}];
        }
    std::vector<Edge> out;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::size_t a = t[k], b = t[(k + 1) % 3];
            if (count[{std::min(a, b), std::max(a, b)}] == 1) out.emplace_back(a, b);
        }
    return out;
}

/// The boundary edges chained into loops of nodes (each loop in edge order).
std::vector<std::vector<std::size_t>> boundaryLoops(const TowMesh& m)
{
    std::multimap<std::size_t, std::size_t> next;
    for (const Edge& e : boundaryEdges(m)) next.emplace(e.first, e.second);
    std::vector<std::vector<std::size_t>> loops;
    while (!next.empty()) {
        std::vector<std::size_t> loop;
        auto it = next.begin();
        const std::size_t first = it->first;
        std::size_t at = first;
        while (it != next.end()) {
            loop.push_back(at);
            const std::size_t to = it->second;
            next.erase(it);
            at = to;
            if (at == first) break;
            it = next.find(at);
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

}  // namespace

TriangleMesh TextileMesh::towSurface(std::size_t tow) const
{
    TriangleMesh out;
    std::map<std::size_t, std::size_t> local;
    for (const auto& t : tows.at(tow).triangles) {
        std::array<std::size_t, 3> r{};
        for (int k = 0; k < 3; ++k) {
            const auto [it, fresh] = local.emplace(t[k], out.vertices.size());
            if (fresh) out.vertices.push_back(nodes.at(t[k]));
            r[k] = it->second;
        }
        out.triangles.push_back(r);
    }
    return out;
}

std::vector<std::size_t> TextileMesh::towNodes(std::size_t tow) const
{
    std::vector<std::size_t> order;
    std::set<std::size_t> seen;
    for (const auto& t : tows.at(tow).triangles)
        for (std::size_t n : t)
            if (seen.insert(n).second) order.push_back(n);
    return order;
}

TriangleMesh TextileMesh::closedTowSurface(std::size_t tow) const
{
    TriangleMesh out = towSurface(tow);
    // Same renumbering as towSurface(): rebuild the map to find the loops' local indices.
    std::map<std::size_t, std::size_t> local;
    for (const auto& t : tows.at(tow).triangles)
        for (int k = 0; k < 3; ++k) local.emplace(t[k], local.size());
    for (const std::vector<std::size_t>& loop : boundaryLoops(tows.at(tow))) {
        Point3 c;
        for (std::size_t n : loop) c = c + nodes[n];
        c = (1.0 / static_cast<double>(loop.size())) * c;
        const std::size_t centre = out.vertices.size();
        out.vertices.push_back(c);
        // Boundary edges run along the loop in triangle order; the cap closes them the other way.
        for (std::size_t k = 0; k < loop.size(); ++k)
            out.triangles.push_back({local.at(loop[(k + 1) % loop.size()]), local.at(loop[k]), centre});
    }
    return out;
}

std::size_t TextileMesh::boundaryLoopCount(std::size_t tow) const { return boundaryLoops(tows.at(tow)).size(); }

}  // namespace towgeom
