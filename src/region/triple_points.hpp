// Triple points: where loops of two tow pairs that share a tow, (t, s1) and (t, s2), cross on
// t, the three tows' surfaces meet in one point, which the loop of (s1, s2) passes through too.
// That point becomes one node of the three loops, so that the three tows' meshes meet in it.
#pragma once

#include <cstddef>
#include <vector>

#include "mesh/loop_nodes.hpp"
#include "towgeom/intersection_loop.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Two loops of different tow pairs that still cross on tow @p tow (their triple point could not
/// be found: no loop of the third pair there, Newton's method did not converge, or the point lies
/// on a seam).
struct CrossingLoops {
    std::size_t tow = 0;
    std::size_t first = 0, second = 0;  ///< indices into the shared loops
};

/// Finds every triple point: where the exact curves of two loops of different tow pairs cross
/// on a tow, refined on the three surfaces (refineTriplePoint). Each is inserted as one new node
/// (appended to @p nodes) into the loop of each of its three pairs with a chord nearest to it;
/// loop nodes closer to it than a quarter of their chord are removed (not seam nodes, nor nodes
/// of several loops). Also returns the loops whose node polygons still cross on a tow: a triple
/// point not found, or one whose third pair has no loop there. @p tows and the loops in one frame.
/// What joinAtTriplePoints() did.
struct TripleJoin {
    std::vector<TriplePoint> points;      ///< the triple nodes inserted
    std::vector<CrossingLoops> crossing;  ///< loops whose node polygons still cross on a tow
};

TripleJoin joinAtTriplePoints(const std::vector<TowSurface>& tows, const std::vector<IntersectionLoop>& loops,
                              std::vector<SharedLoop>& shared, std::vector<Point3>& nodes);

}  // namespace detail
TOWGEOM_END_NAMESPACE
