#include "mesh/crossing_spots.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <tuple>

#include "mesh/crossing_triangles.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

CrossingSpots crossingSpots(const std::vector<Point3>& nodes, const std::vector<ParametricMesh>& meshes,
                            const std::vector<std::vector<Point3>>& ownNodes, std::size_t ownFrom, const std::vector<CapMesh>& caps,
                            const std::set<std::pair<std::size_t, std::size_t>>& ignored,
                            const std::function<bool(const std::pair<std::size_t, std::size_t>&, std::size_t)>& refined,
                            std::size_t threads)
{
    // Each tow's tube, then its caps (their nodes after its own).
    std::vector<std::vector<std::array<std::size_t, 3>>> triangles(caps.empty() ? 0 : meshes.size());
    std::vector<std::vector<Point3>> own(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        triangles[t] = meshes[t].triangles;
        triangles[t].insert(triangles[t].end(), caps[t].triangles.begin(), caps[t].triangles.end());
        own[t] = ownNodes[t];
        own[t].insert(own[t].end(), caps[t].newNodes.begin(), caps[t].newNodes.end());
    }
    const auto allTriangles = [&](std::size_t t) -> const std::vector<std::array<std::size_t, 3>>& { return caps.empty() ? meshes[t].triangles : triangles[t]; };
    const auto allOwn = [&](std::size_t t) -> const std::vector<Point3>& { return caps.empty() ? ownNodes[t] : own[t]; };
    std::vector<TowTriangles> tows(meshes.size());
    for (std::size_t t = 0; t < meshes.size(); ++t) tows[t] = {&allTriangles(t), &allOwn(t)};
    const std::vector<CrossingTriangles> crossing = crossingTriangles(nodes, ownFrom, tows, ignored, threads);
    const auto node = [&](std::size_t t, std::size_t n) -> const Point3& { return n < ownFrom ? nodes[n] : allOwn(t)[n - ownFrom]; };
    const auto longestEdge = [&](std::size_t t, std::size_t k) {
        const std::array<std::size_t, 3>& x = allTriangles(t)[k];
        return std::max({distance(node(t, x[0]), node(t, x[1])), distance(node(t, x[1]), node(t, x[2])), distance(node(t, x[2]), node(t, x[0]))});
    };
    const auto onTube = [&](std::size_t t, std::size_t k) { return k < meshes[t].triangles.size(); };
    const auto centroid = [&](std::size_t t, std::size_t k) {
        const std::array<std::size_t, 3>& x = allTriangles(t)[k];
        return (1.0 / 3.0) * (node(t, x[0]) + node(t, x[1]) + node(t, x[2]));
    };
    // Where tow t's cap crosses a tube at @p at: the tube's own node nearest to it (the cap's rim
    // is the tube's end, refined there) and its distance.
    const auto nearestOnTube = [&](std::size_t t, const Point3& at) {
        std::pair<std::size_t, double> best{0, std::numeric_limits<double>::infinity()};
        for (std::size_t n = 0; n < ownNodes[t].size(); ++n)
            if (const double d = distance(ownNodes[t][n], at); d < best.second) best = {n, d};
        return best;
    };
    CrossingSpots out;
    out.spots.resize(meshes.size());
    for (const CrossingTriangles& c : crossing) ++out.crossingPairs[{c.towA, c.towB}];
    for (const CrossingTriangles& c : crossing) {
        if (!refined({c.towA, c.towB}, out.crossingPairs[{c.towA, c.towB}])) continue;
        const bool tubeA = onTube(c.towA, c.triangleA), tubeB = onTube(c.towB, c.triangleB);
        const double a = longestEdge(c.towA, c.triangleA), b = longestEdge(c.towB, c.triangleB);
        if (tubeA && tubeB) {
            const double size = 0.5 * std::min(a, b), radius = 2.0 * std::max(a, b);
            out.spots[c.towA].push_back({meshes[c.towA].centroids[c.triangleA], radius, size});
            out.spots[c.towB].push_back({meshes[c.towB].centroids[c.triangleB], radius, size});
            continue;
        }
        // A cap is flat, as exact as it is; its rim is its tube's end. The tube crossing it is
        // refined by its own triangle's size, and the cap's own tube (its end's stations) around
        // its node nearest to that triangle.
        for (const auto& [cap, tube, k, length] : {std::tuple{c.towA, c.towB, c.triangleB, b}, std::tuple{c.towB, c.towA, c.triangleA, a}}) {
            if (onTube(tube, k)) out.spots[tube].push_back({meshes[tube].centroids[k], 2.0 * length, 0.5 * length});
            if (!onTube(tube, k) || ownNodes[cap].empty()) continue;
            const auto [n, d] = nearestOnTube(cap, centroid(tube, k));
            // (Not for a crossing inside the cap, farther from its tube than the cap triangle is
            // long: refining the tube would not change the cap there.)
            if (d > longestEdge(cap, cap == c.towA ? c.triangleA : c.triangleB)) continue;
            out.spots[cap].push_back({meshes[cap].newNodes[n], d + 2.0 * length, 0.5 * length});
        }
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
