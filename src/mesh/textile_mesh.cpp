#include "towgeom/textile_mesh.hpp"

#include "mesh/mesh_measures.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <map>
#include <unordered_map>
#include <utility>
#include <cstdint>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Edge = std::pair<std::size_t, std::size_t>;

/// How a triangle soup uses its edges: the directed boundary edges (used by one triangle only,
/// as (from, to) in triangle order), and the edges that make it no oriented 2-manifold (used by
/// more than two triangles, or twice the same way round).
struct EdgeUse {
    std::vector<Edge> boundary;
    std::size_t bad = 0;
};

EdgeUse edgeUse(const std::vector<std::array<std::size_t, 3>>& triangles)
{
    EdgeUse out;
    const bool packed = std::all_of(triangles.begin(), triangles.end(), [](const auto& t) {
        return std::max({t[0], t[1], t[2]}) < (std::size_t(1) << 31);
    });
    if (packed) {
        // Each half-edge as one 64-bit key: the larger node, the smaller one, and whether it runs
        // from the larger (sorting plain integers: a third of the time of the records below, on
        // meshes of millions of triangles). Key >> 1 is the undirected edge.
        std::vector<std::uint64_t> halves;
        halves.reserve(3 * triangles.size());
        for (const auto& t : triangles)
            for (int k = 0; k < 3; ++k) {
                const std::uint64_t a = t[k], b = t[(k + 1) % 3];
                const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
                halves.push_back((hi << 32) | (lo << 1) | (a > b ? 1u : 0u));
            }
        std::sort(halves.begin(), halves.end());
        const auto from = [](std::uint64_t h) { return (h & 1u) ? h >> 32 : (h >> 1) & 0x7fffffffu; };
        const auto to = [](std::uint64_t h) { return (h & 1u) ? (h >> 1) & 0x7fffffffu : h >> 32; };
        for (std::size_t i = 0; i < halves.size();) {
            std::size_t j = i + 1;
            while (j < halves.size() && (halves[j] >> 1) == (halves[i] >> 1)) ++j;
            if (j == i + 1) out.boundary.emplace_back(from(halves[i]), to(halves[i]));
            if (j > i + 2 || (j == i + 2 && halves[i] == halves[i + 1]) || from(halves[i]) == to(halves[i])) ++out.bad;
            i = j;
        }
        return out;
    }
    struct Half {
        std::size_t from, to;
    };
    std::vector<Half> halves;
    halves.reserve(3 * triangles.size());
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) halves.push_back({t[k], t[(k + 1) % 3]});
    const auto less = [](const Half& x, const Half& y) { return std::minmax(x.from, x.to) < std::minmax(y.from, y.to); };
    std::sort(halves.begin(), halves.end(), less);
    for (std::size_t i = 0; i < halves.size();) {
        std::size_t j = i + 1;
        while (j < halves.size() && !less(halves[i], halves[j])) ++j;
        if (j == i + 1) out.boundary.emplace_back(halves[i].from, halves[i].to);
        if (j > i + 2 || (j == i + 2 && halves[i].from == halves[i + 1].from) || halves[i].from == halves[i].to) ++out.bad;
        i = j;
    }
    return out;
}

/// Directed boundary edges chained into loops of nodes, each in the direction its edges run.
std::vector<std::vector<std::size_t>> chainLoops(const std::vector<Edge>& boundary)
{
    std::multimap<std::size_t, std::size_t> next;
    for (const Edge& e : boundary) next.emplace(e.first, e.second);
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

/// signedVolume() plus the fans closing @p loops (boundary loops of @p triangles).
double fannedVolume(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles,
                    const std::vector<std::vector<std::size_t>>& loops);

}  // namespace

namespace detail {

std::vector<std::vector<std::size_t>> boundaryLoops(const std::vector<std::array<std::size_t, 3>>& triangles)
{
    return chainLoops(edgeUse(triangles).boundary);
}

}  // namespace detail

namespace {

using detail::boundaryLoops;

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

namespace detail {

double windingNumber(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles, const Point3& p)
{
    double sum = 0.0;
    for (const auto& t : triangles) {
        const Vector3 a = nodes[t[0]] - p, b = nodes[t[1]] - p, c = nodes[t[2]] - p;
        const double la = norm(a), lb = norm(b), lc = norm(c);
        const double numerator = dot(a, cross(b, c));
        const double denominator = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
        sum += 2.0 * std::atan2(numerator, denominator);
    }
    return sum / (4.0 * 3.14159265358979323846);
}

double signedVolume(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles)
{
    if (triangles.empty()) return 0.0;
    const Point3 o = nodes[triangles.front()[0]];  // near the mesh: less cancellation than the origin
    double sum = 0.0;
    for (const auto& t : triangles) sum += dot(nodes[t[0]] - o, cross(nodes[t[1]] - o, nodes[t[2]] - o));
    return sum / 6.0;
}

std::size_t connectedPieces(const std::vector<std::array<std::size_t, 3>>& triangles)
{
    // Union-find over the node numbers (SIZE_MAX: a node no triangle uses).
    std::size_t top = 0;
    for (const auto& t : triangles) top = std::max({top, t[0] + 1, t[1] + 1, t[2] + 1});
    std::vector<std::size_t> parent(top, SIZE_MAX);
    for (const auto& t : triangles)
        for (const std::size_t n : t) parent[n] = n;
    const auto find = [&](std::size_t n) {
        std::size_t root = n;
        while (parent[root] != root) root = parent[root];
        while (parent[n] != root) n = std::exchange(parent[n], root);
        return root;
    };
    for (const auto& t : triangles) {
        const std::size_t a = find(t[0]);
        parent[find(t[1])] = a;
        parent[find(t[2])] = a;
    }
    std::size_t roots = 0;
    for (std::size_t n = 0; n < top; ++n) roots += parent[n] == n;
    return roots;
}

double closedVolume(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles,
                    std::size_t* loopCount)
{
    const std::vector<std::vector<std::size_t>> loops = boundaryLoops(triangles);
    if (loopCount) *loopCount = loops.size();
    return fannedVolume(nodes, triangles, loops);
}

SurfaceFigures surfaceFigures(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles)
{
    const EdgeUse use = edgeUse(triangles);
    const std::vector<std::vector<std::size_t>> loops = chainLoops(use.boundary);
    SurfaceFigures f;
    f.volume = fannedVolume(nodes, triangles, loops);
    f.boundaryLoops = loops.size();
    f.badEdges = use.bad;
    for (const auto& t : triangles) f.area += triangleArea(nodes, t);
    return f;
}

double triangleArea(const std::vector<Point3>& nodes, const std::array<std::size_t, 3>& t)
{
    return 0.5 * norm(cross(nodes[t[1]] - nodes[t[0]], nodes[t[2]] - nodes[t[0]]));
}

double smallestAngle(const std::vector<Point3>& nodes, const std::array<std::size_t, 3>& t)
{
    double best = 180.0;
    for (int k = 0; k < 3; ++k) {
        const Vector3 a = nodes[t[(k + 1) % 3]] - nodes[t[k]], b = nodes[t[(k + 2) % 3]] - nodes[t[k]];
        best = std::min(best, std::atan2(norm(cross(a, b)), dot(a, b)) * 180.0 / 3.14159265358979323846);
    }
    return best;
}

std::string notClosedMessage(bool caps, std::size_t badEdges, std::size_t boundaryLoops)
{
    return std::string(caps ? "the mesh is not a closed surface (" : "the mesh is not a tube open at its two ends (") +
           std::to_string(badEdges) + " edges not shared by exactly two triangles the opposite way round, " +
           std::to_string(boundaryLoops) + " boundary loops)";
}

}  // namespace detail

namespace {

double fannedVolume(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles,
                    const std::vector<std::vector<std::size_t>>& loops)
{
    double volume = detail::signedVolume(nodes, triangles);
    if (triangles.empty()) return volume;
    const Point3 o = nodes[triangles.front()[0]];
    for (const std::vector<std::size_t>& loop : loops) {
        Point3 c;
        for (std::size_t n : loop) c = c + nodes[n];
        c = (1.0 / static_cast<double>(loop.size())) * c;
        // The cap's fan, the other way round the loop than the boundary edges run.
        for (std::size_t k = 0; k < loop.size(); ++k)
            volume += dot(nodes[loop[(k + 1) % loop.size()]] - o, cross(nodes[loop[k]] - o, c - o)) / 6.0;
    }
    return volume;
}

}  // namespace

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

TOWGEOM_END_NAMESPACE
