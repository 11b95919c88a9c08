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
/// surface S_A, inside the secondary) and the point q of the secondary's surface S_B such that
/// q - p runs along the common normal, the mean of S_A's inward normal at p and S_B's outward
/// normal at q (the same construction with the roles swapped). Solved on S_B's exact surface:
/// fixed-point iteration on the direction, Newton's method for q along each; seeded by the first
/// hit of the ray from p along -n_A on the secondary's triangles inside the loop (CGAL's AABB
/// tree), or their nearest point where that ray misses them. One position per movable node, in
/// order. Returns false and sets @p why when a node's q is not found (the region keeps the
/// primary's surface then).
bool midSurfacePositions(const MidSurfaceRegion& region, const std::vector<Point3>& nodes, std::vector<Point3>& positions,
                         std::string& why);

}  // namespace detail
TOWGEOM_END_NAMESPACE
