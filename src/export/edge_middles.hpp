// The middle nodes of a quadratic volume mesh's edges, looked up by the edge's two corners: for
// node sets that must hold the middle nodes on them too, and for 6-node surface triangles.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "towgeom/volume_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

class EdgeMiddles {
public:
    /// Empty for linear tetrahedra.
    explicit EdgeMiddles(const VolumeMesh& volumes)
    {
        constexpr int kEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
        for (std::size_t k = 0; k < volumes.edgeNodes.size() && k < volumes.tetrahedra.size(); ++k)
            for (int e = 0; e < 6; ++e)
                middle_.emplace(key(volumes.tetrahedra[k][static_cast<std::size_t>(kEdges[e][0])],
                                    volumes.tetrahedra[k][static_cast<std::size_t>(kEdges[e][1])]),
                                volumes.edgeNodes[k][static_cast<std::size_t>(e)]);
    }
    bool empty() const { return middle_.empty(); }
    /// The middle node of edge (@p a, @p b), if the mesh has that edge.
    const std::size_t* of(std::size_t a, std::size_t b) const
    {
        const auto it = middle_.find(key(a, b));
        return it == middle_.end() ? nullptr : &it->second;
    }
    /// @p nodes (sorted) with the middle nodes of every edge whose two corners are in it (a plane
    /// face's set: those edges lie in the face), sorted.
    std::vector<std::size_t> withMiddles(std::vector<std::size_t> nodes) const
    {
        if (middle_.empty()) return nodes;
        const std::size_t corners = nodes.size();
        for (const auto& [edge, mid] : middle_)
            if (std::binary_search(nodes.begin(), nodes.begin() + static_cast<long>(corners), edge.first) &&
                std::binary_search(nodes.begin(), nodes.begin() + static_cast<long>(corners), edge.second))
                nodes.push_back(mid);
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        return nodes;
    }
    /// Every edge and its middle node.
    const std::map<std::pair<std::size_t, std::size_t>, std::size_t>& all() const { return middle_; }

private:
    static std::pair<std::size_t, std::size_t> key(std::size_t a, std::size_t b) { return std::minmax(a, b); }
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle_;
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
