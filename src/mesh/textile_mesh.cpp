#include "towgeom/textile_mesh.hpp"

#include <algorithm>
#include <map>
#include <cstdint>

namespace towgeom {

namespace {

using Edge = std::pair<std::size_t, std::size_t>;

/// Directed boundary edges (used by one triangle only), as (from, to) in triangle order.
std::vector<Edge> boundaryEdges(const std::vector<std::array<std::size_t, 3>>& triangles)
{
    std::vector<Edge> undirected;
    undirected.reserve(3 * triangles.size());
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) undirected.emplace_back(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
    std::sort(undirected.begin(), undirected.end());
    std::vector<Edge> once;
    for (std::size_t i = 0; i < undirected.size();) {
        std::size_t j = i + 1;
        while (j < undirected.size() && undirected[j] == undirected[i]) ++j;
        if (j == i + 1) once.push_back(undirected[i]);
        i = j;
    }
    std::vector<Edge> out;
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) {
            const Edge e{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])};
            if (std::binary_search(once.begin(), once.end(), e)) out.emplace_back(t[k], t[(k + 1) % 3]);
        }
    return out;
}

/// The boundary edges chained into loops of nodes (each loop in edge order).
std::vector<std::vector<std::size_t>> boundaryLoops(const std::vector<std::array<std::size_t, 3>>& triangles)
{
    std::multimap<std::size_t, std::size_t> next;
    for (const Edge& e : boundaryEdges(triangles)) next.emplace(e.first, e.second);
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

/// The triangles over their own nodes, renumbered in order of first use; @p used gets the
/// global node of each local one.
TriangleMesh renumbered(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles,
                        std::vector<std::size_t>& used)
{
    TriangleMesh out;
    std::vector<std::size_t> local(nodes.size(), SIZE_MAX);
    used.clear();
    out.triangles.reserve(triangles.size());
    for (const auto& t : triangles) {
        std::array<std::size_t, 3> r{};
        for (int k = 0; k < 3; ++k) {
            if (local[t[k]] == SIZE_MAX) {
                local[t[k]] = used.size();
                used.push_back(t[k]);
                out.vertices.push_back(nodes[t[k]]);
            }
            r[k] = local[t[k]];
        }
        out.triangles.push_back(r);
    }
    return out;
}

}  // namespace

TriangleMesh closedSurface(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles)
{
    std::vector<std::size_t> used;
    TriangleMesh out = renumbered(nodes, triangles, used);
    std::vector<std::size_t> local(nodes.size(), SIZE_MAX);
    for (std::size_t k = 0; k < used.size(); ++k) local[used[k]] = k;
    for (const std::vector<std::size_t>& loop : boundaryLoops(triangles)) {
        Point3 c;
        for (std::size_t n : loop) c = c + nodes[n];
        c = (1.0 / static_cast<double>(loop.size())) * c;
        const std::size_t centre = out.vertices.size();
        out.vertices.push_back(c);
        // Boundary edges run along the loop in triangle order; the cap closes them the other way.
        for (std::size_t k = 0; k < loop.size(); ++k)
            out.triangles.push_back({local[loop[(k + 1) % loop.size()]], local[loop[k]], centre});
    }
    return out;
}

TriangleMesh surfaceOf(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles)
{
    std::vector<std::size_t> used;
    return renumbered(nodes, triangles, used);
}

TriangleMesh TextileMesh::towSurface(std::size_t tow) const { return surfaceOf(nodes, tows.at(tow).triangles); }

std::vector<std::size_t> TextileMesh::towNodes(std::size_t tow) const
{
    std::vector<std::size_t> used;
    renumbered(nodes, tows.at(tow).triangles, used);
    return used;
}

TriangleMesh TextileMesh::closedTowSurface(std::size_t tow) const { return closedSurface(nodes, tows.at(tow).triangles); }

std::size_t TextileMesh::boundaryLoopCount(std::size_t tow) const { return boundaryLoops(tows.at(tow).triangles).size(); }

}  // namespace towgeom
