#include "cell/box_edges.hpp"

#include <algorithm>
#include <cmath>

#include "cell/axis.hpp"
#include "cell/face_size.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

BoxEdges::BoxEdges(const Cell& cell, double h, std::vector<Point3>& nodes, std::vector<std::size_t> onEdges,
                   std::set<std::pair<std::size_t, std::size_t>> whole)
    : cell_(cell), h_(h), nodes_(nodes), onEdges_(std::move(onEdges)), whole_(std::move(whole))
{
}

const std::vector<std::size_t>& BoxEdges::edge(int e, std::array<int, 3> side)
{
    side[static_cast<std::size_t>(e)] = -1;
    const std::array<int, 4> key{e, side[0], side[1], side[2]};
    auto it = edges_.find(key);
    if (it != edges_.end()) return it->second;
    const double lo = coord(cell_.min, e), hi = coord(cell_.max, e);
    const Point3 line = pointAt(side);
    // The given nodes on this edge, between its corners.
    std::vector<std::size_t> through;
    for (std::size_t n : onEdges_) {
        bool on = coord(nodes_[n], e) > lo && coord(nodes_[n], e) < hi;
        for (int b = 0; b < 3; ++b)
            if (b != e && coord(nodes_[n], b) != coord(line, b)) on = false;
        if (on) through.push_back(n);
    }
    std::sort(through.begin(), through.end(), [&](std::size_t x, std::size_t y) { return coord(nodes_[x], e) < coord(nodes_[y], e); });
    std::array<int, 3> at = side;
    at[static_cast<std::size_t>(e)] = 0;
    std::vector<std::size_t> list{corner(at)};
    // From the last node listed to the next fixed one (coordinate @p to, node @p next once made).
    const auto divideTo = [&](double to, long next) {
        const std::size_t from = list.back();
        if (next >= 0 && whole_.count(std::minmax(from, static_cast<std::size_t>(next)))) return;
        const double start = coord(nodes_[from], e);
        const std::size_t n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil((to - start) / h_)));
        for (std::size_t i = 1; i < n; ++i) {
            Point3 p = line;
            coord(p, e) = start + (to - start) * static_cast<double>(i) / static_cast<double>(n);
            list.push_back(nodes_.size());
            nodes_.push_back(p);
        }
    };
    for (std::size_t n : through) {
        divideTo(coord(nodes_[n], e), static_cast<long>(n));
        list.push_back(n);
    }
    at[static_cast<std::size_t>(e)] = 1;
    const std::size_t last = corner(at);
    divideTo(hi, static_cast<long>(last));
    list.push_back(last);
    return edges_.emplace(key, std::move(list)).first->second;
}

std::vector<std::size_t> BoxEdges::rectangle(int a, int s)
{
    const auto [b, c] = inPlane(a);
    std::array<int, 3> side{};
    side[static_cast<std::size_t>(a)] = s;
    std::vector<std::size_t> out;
    const auto append = [&](std::vector<std::size_t> part, bool backwards) {
        if (backwards) std::reverse(part.begin(), part.end());
        out.insert(out.end(), part.begin(), part.end() - 1);  // the last is the next part's first
    };
    side[static_cast<std::size_t>(c)] = 0;
    append(edge(b, side), false);
    side[static_cast<std::size_t>(b)] = 1;
    append(edge(c, side), false);
    side[static_cast<std::size_t>(c)] = 1;
    append(edge(b, side), true);
    side[static_cast<std::size_t>(b)] = 0;
    append(edge(c, side), true);
    return out;
}

std::size_t BoxEdges::corner(const std::array<int, 3>& side)
{
    const int key = side[0] + 2 * side[1] + 4 * side[2];
    auto it = corners_.find(key);
    if (it != corners_.end()) return it->second;
    const Point3 p = pointAt(side);
    for (std::size_t n : onEdges_)
        if (nodes_[n].x == p.x && nodes_[n].y == p.y && nodes_[n].z == p.z) return corners_.emplace(key, n).first->second;
    nodes_.push_back(p);
    return corners_.emplace(key, nodes_.size() - 1).first->second;
}

Point3 BoxEdges::pointAt(const std::array<int, 3>& side) const
{
    Point3 p;
    for (int a = 0; a < 3; ++a) coord(p, a) = side[static_cast<std::size_t>(a)] == 1 ? coord(cell_.max, a) : coord(cell_.min, a);
    return p;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
