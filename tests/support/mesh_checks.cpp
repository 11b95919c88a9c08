#include "mesh_checks.hpp"

#include <map>
#include <set>
#include <utility>

namespace towgeom::testing {

Boundary boundaryOf(const std::vector<std::array<std::size_t, 3>>& triangles)
{
    std::map<std::pair<std::size_t, std::size_t>, int> directed;
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    std::map<std::pair<std::size_t, std::size_t>, std::pair<int, int>> undirected;  // (forward, backward)
    for (const auto& [e, n] : directed) {
        if (e.first < e.second)
            undirected[e].first += n;
        else
            undirected[{e.second, e.first}].second += n;
    }
    Boundary b;
    std::map<std::size_t, std::vector<std::size_t>> adjacent;
    for (const auto& [e, n] : undirected) {
        const int uses = n.first + n.second;
        if (uses == 1) {
            ++b.edges;
            adjacent[e.first].push_back(e.second);
            adjacent[e.second].push_back(e.first);
        } else if (uses > 2) {
            ++b.nonManifoldEdges;
        } else if (n.first != 1 || n.second != 1) {
            ++b.misorientedEdges;
        }
    }
    std::set<std::size_t> seen;
    for (const auto& [node, next] : adjacent) {
        if (next.size() != 2) ++b.nodesNotTwo;
        if (seen.count(node)) continue;
        ++b.loops;
        std::vector<std::size_t> stack{node};
        seen.insert(node);
        while (!stack.empty()) {
            const std::size_t at = stack.back();
            stack.pop_back();
            for (std::size_t n : adjacent[at])
                if (seen.insert(n).second) stack.push_back(n);
        }
    }
    return b;
}

}  // namespace towgeom::testing
