// The middle nodes of a quadratic volume mesh's edges, looked up by the edge's two corners: for
// the middle nodes of a node set's triangles (faces, caps), the periodic ties and 6-node
// surface triangles.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

#include "towgeom/error.hpp"
#include "towgeom/volume_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

class EdgeMiddles {
public:
    /// One edge: its corners (ascending) and its middle node.
    struct Edge {
        std::size_t a = 0, b = 0, middle = 0;
    };
    /// Empty for linear tetrahedra.
    /// @throws Error (InvalidArgument) if @p volumes names a node it does not have or has middle
    /// nodes for some tetrahedra only.
    explicit EdgeMiddles(const VolumeMesh& volumes)
    {
        if (volumes.edgeNodes.empty()) return;
        if (volumes.edgeNodes.size() != volumes.tetrahedra.size())
            throw Error(ErrorCode::InvalidArgument, "the volume mesh has middle nodes for some of its tetrahedra only");
        constexpr int kEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
        edges_.reserve(6 * volumes.tetrahedra.size());
        for (std::size_t k = 0; k < volumes.tetrahedra.size(); ++k)
            for (int e = 0; e < 6; ++e) {
                const std::size_t a = volumes.tetrahedra[k][static_cast<std::size_t>(kEdges[e][0])];
                const std::size_t b = volumes.tetrahedra[k][static_cast<std::size_t>(kEdges[e][1])];
                const std::size_t m = volumes.edgeNodes[k][static_cast<std::size_t>(e)];
                if (m >= volumes.nodes.size()) throw Error(ErrorCode::InvalidArgument, "a tetrahedron names a middle node out of range");
                edges_.push_back({std::min(a, b), std::max(a, b), m});
            }
        std::sort(edges_.begin(), edges_.end(), [](const Edge& x, const Edge& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
        edges_.erase(std::unique(edges_.begin(), edges_.end(), [](const Edge& x, const Edge& y) { return x.a == y.a && x.b == y.b; }),
                     edges_.end());
    }
    bool empty() const { return edges_.empty(); }
    /// The middle node of edge (@p a, @p b), if the mesh has that edge.
    const std::size_t* of(std::size_t a, std::size_t b) const
    {
        const Edge key{std::min(a, b), std::max(a, b), 0};
        const auto it = std::lower_bound(edges_.begin(), edges_.end(), key,
                                         [](const Edge& x, const Edge& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
        return it != edges_.end() && it->a == key.a && it->b == key.b ? &it->middle : nullptr;
    }
    /// @p nodes with the middle nodes of @p triangles' edges (the set's own triangles), sorted.
    template <class Triangles>
    std::vector<std::size_t> withMiddles(std::vector<std::size_t> nodes, const Triangles& triangles) const
    {
        if (!edges_.empty())
            for (const std::array<std::size_t, 3>& t : triangles)
                for (int e = 0; e < 3; ++e)
                    if (const std::size_t* m = of(t[static_cast<std::size_t>(e)], t[static_cast<std::size_t>((e + 1) % 3)])) nodes.push_back(*m);
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        return nodes;
    }
    /// Every edge and its middle node, by corners.
    const std::vector<Edge>& all() const { return edges_; }

private:
    std::vector<Edge> edges_;
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
