#include "mesh/crossing_spots.hpp"

#include <algorithm>
#include <array>

#include "mesh/crossing_triangles.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

CrossingSpots crossingSpots(const std::vector<Point3>& nodes, const std::vector<ParametricMesh>& meshes,
                            const std::vector<std::vector<Point3>>& ownNodes, std::size_t ownFrom,
                            const std::set<std::pair<std::size_t, std::size_t>>& ignored,
                            const std::function<bool(const std::pair<std::size_t, std::size_t>&, std::size_t)>& refined,
                            std::size_t threads)
{
    std::vector<TowTriangles> tows(meshes.size());
    for (std::size_t t = 0; t < meshes.size(); ++t) tows[t] = {&meshes[t].triangles, &ownNodes[t]};
    const std::vector<CrossingTriangles> crossing = crossingTriangles(nodes, ownFrom, tows, ignored, threads);
    const auto node = [&](std::size_t t, std::size_t n) -> const Point3& { return n < ownFrom ? nodes[n] : ownNodes[t][n - ownFrom]; };
    const auto longestEdge = [&](std::size_t t, std::size_t k) {
        const std::array<std::size_t, 3>& x = meshes[t].triangles[k];
        return std::max({distance(node(t, x[0]), node(t, x[1])), distance(node(t, x[1]), node(t, x[2])), distance(node(t, x[2]), node(t, x[0]))});
    };
    CrossingSpots out;
    out.spots.resize(meshes.size());
    for (const CrossingTriangles& c : crossing) ++out.crossingPairs[{c.towA, c.towB}];
    for (const CrossingTriangles& c : crossing) {
        if (!refined({c.towA, c.towB}, out.crossingPairs[{c.towA, c.towB}])) continue;
        const double a = longestEdge(c.towA, c.triangleA), b = longestEdge(c.towB, c.triangleB);
        const double size = 0.5 * std::min(a, b), radius = 2.0 * std::max(a, b);
        out.spots[c.towA].push_back({meshes[c.towA].centroids[c.triangleA], radius, size});
        out.spots[c.towB].push_back({meshes[c.towB].centroids[c.triangleB], radius, size});
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
