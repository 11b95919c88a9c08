// The nodes of a cell's corners and edges, made once and shared by the two faces that meet at
// each edge: the box's edges divided at the faces' mesh size, through any given nodes that lie
// on them (where a tow's clipped surface meets an edge of the box).
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "towgeom/cell.hpp"
#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

class BoxEdges {
public:
    /// Edges of @p cell divided at @p h; new nodes go to @p nodes. @p onEdges: nodes exactly on
    /// an edge of the box (two of their coordinates equal to the box's), which the edge passes
    /// through (one at a corner is that corner); @p whole: pairs of them joined by an edge of a
    /// tow's mesh, not divided.
    BoxEdges(const Cell& cell, double h, std::vector<Point3>& nodes, std::vector<std::size_t> onEdges = {},
             std::set<std::pair<std::size_t, std::size_t>> whole = {});
    /// The nodes along the edge parallel to axis @p e at the sides @p side of the other two axes
    /// (0 min, 1 max; side[e] ignored), in increasing coordinate e, both corners included.
    const std::vector<std::size_t>& edge(int e, std::array<int, 3> side);
    /// The rectangle of the face across axis @p a at side @p s, counter-clockwise in its (b, c)
    /// plane (inPlane()), from its (min, min) corner, each node once.
    std::vector<std::size_t> rectangle(int a, int s);

private:
    std::size_t corner(const std::array<int, 3>& side);
    Point3 pointAt(const std::array<int, 3>& side) const;

    const Cell& cell_;
    double h_;
    std::vector<Point3>& nodes_;
    std::vector<std::size_t> onEdges_;
    std::set<std::pair<std::size_t, std::size_t>> whole_;
    std::map<std::array<int, 4>, std::vector<std::size_t>> edges_;
    std::map<int, std::size_t> corners_;
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
