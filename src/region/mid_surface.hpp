// The mid-surface of a connected region (ResolutionMethod::Symmetric): both tows give way to the
// surface halfway between them, so each loses about half of their overlap.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// One region as the mid-surface needs it: both tows, their nodes' (u,v) (TowMesh::parameters,
/// sorted by node), the primary's triangles inside the loop and the secondary's.
struct MidSurfaceRegion {
    const TowSurface* primary = nullptr;
    const TowSurface* secondary = nullptr;
    const std::vector<std::pair<std::size_t, UV>>* primaryParameters = nullptr;
    const std::vector<std::pair<std::size_t, UV>>* secondaryParameters = nullptr;
    std::vector<std::array<std::size_t, 3>> secondaryTriangles;  ///< the secondary's surface inside the loop
    std::vector<std::size_t> movable;  ///< the region's nodes off every loop (each on the primary's surface)
};

/// Where each of @p region's movable nodes goes: the midpoint between the node p (on the primary's
/// surface S_A, inside the secondary) and the point q where the line from p along -n_A (S_A's
/// outward normal, into the primary) meets the secondary's surface S_B, solved exactly on S_B (by
/// Newton's method from the first hit of that ray on the secondary's triangles inside the loop,
/// CGAL's AABB tree). One position per movable node, in order. Returns false and sets @p why when
/// a node's line meets no secondary triangle inside the loop or Newton's method does not converge
/// (the region keeps the primary's surface then).
bool midSurfacePositions(const MidSurfaceRegion& region, const std::vector<Point3>& nodes, std::vector<Point3>& positions,
                         std::string& why);

}  // namespace detail
TOWGEOM_END_NAMESPACE
