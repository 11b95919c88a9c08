#include "region/mesh_pieces.hpp"

#include <algorithm>
#include <numeric>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

MeshPieces::Edge edgeKey(std::size_t a, std::size_t b) { return {std::min(a, b), std::max(a, b)}; }

std::size_t root(std::vector<std::size_t>& parent, std::size_t k)
{
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
}

}  // namespace

MeshPieces::MeshPieces(const std::vector<std::array<std::size_t, 3>>& triangles) : triangleCount_(triangles.size())
{
    edges_.reserve(3 * triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) edges_.emplace_back(edgeKey(triangles[t][k], triangles[t][(k + 1) % 3]), t);
    std::sort(edges_.begin(), edges_.end());
}

std::vector<std::size_t> MeshPieces::inside(const std::vector<std::size_t>& loopNodes, const std::vector<std::size_t>& inside,
                                            const std::vector<bool>& tested) const
{
    if (loopNodes.size() < 3 || inside.empty() || tested.size() != triangleCount_) return inside;
    std::vector<Edge> chords;
    chords.reserve(loopNodes.size());
    for (std::size_t k = 0; k < loopNodes.size(); ++k) chords.push_back(edgeKey(loopNodes[k], loopNodes[(k + 1) % loopNodes.size()]));
    std::sort(chords.begin(), chords.end());
    chords.erase(std::unique(chords.begin(), chords.end()), chords.end());
    std::vector<std::size_t> parent(triangleCount_);
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    std::vector<std::pair<std::size_t, std::size_t>> across;  // the range in edges_ of each chord
    for (std::size_t i = 0; i < edges_.size();) {
        std::size_t j = i + 1;
        while (j < edges_.size() && edges_[j].first == edges_[i].first) ++j;
        if (std::binary_search(chords.begin(), chords.end(), edges_[i].first))
            across.emplace_back(i, j);
        else
            for (std::size_t k = i + 1; k < j; ++k) parent[root(parent, edges_[k].second)] = root(parent, edges_[i].second);
        i = j;
    }
    if (across.size() != chords.size()) return inside;  // a chord is no edge of the mesh
    for (const auto& [i, j] : across)
        for (std::size_t k = i + 1; k < j; ++k)
            if (root(parent, edges_[k].second) == root(parent, edges_[i].second)) return inside;  // the loop cuts nothing off
    std::vector<std::size_t> count(triangleCount_, 0), votes(triangleCount_, 0);
    for (std::size_t t = 0; t < triangleCount_; ++t)
        if (tested[t]) ++count[root(parent, t)];
    for (std::size_t t : inside)
        if (t < triangleCount_ && tested[t]) ++votes[root(parent, t)];
    std::vector<std::size_t> out;
    for (std::size_t t = 0; t < triangleCount_; ++t) {
        if (!tested[t]) continue;
        const std::size_t r = root(parent, t);
        const double share = static_cast<double>(votes[r]) / static_cast<double>(count[r]);
        if (share > 0.9 || (share >= 0.1 && std::binary_search(inside.begin(), inside.end(), t))) out.push_back(t);
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
