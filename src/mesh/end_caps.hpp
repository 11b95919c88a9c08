// End caps: a tow's mesh closed by the planar polygons of its two ends, each meshed by CGAL's 2D
// constrained Delaunay mesher in its plane with the tube's end nodes as they are.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// One cap's triangles and its own new nodes.
struct CapMesh {
    /// Over global nodes; the cap's own nodes are numbered from the firstNewNode given on.
    std::vector<std::array<std::size_t, 3>> triangles;
    std::vector<Point3> newNodes;  ///< positions of the cap's own nodes, in the cap's plane
};

/// Meshes the polygon of global nodes @p loop (a boundary loop of an outward-oriented tube, in
/// the direction its triangles run along it) in its plane (Newell's normal through its centroid):
/// CGAL's constrained Delaunay triangulation of the polygon, refined to edges of about @p h and
/// the smallest angle @p minAngle without splitting the boundary (a split would be a node the
/// tube lacks). The triangles run along the loop the other way round, so tube and cap make a
/// closed, consistently oriented surface.
/// @throws Error (SelfIntersectingSection) naming @p where when the loop is no simple polygon in
/// its plane (resolveTextile() turns it into InvalidArgument: the mesh size is too coarse for
/// the section).
CapMesh meshCap(const std::vector<Point3>& nodes, const std::vector<std::size_t>& loop, double h, double minAngle,
                std::size_t firstNewNode, const std::string& where);

}  // namespace detail
TOWGEOM_END_NAMESPACE
