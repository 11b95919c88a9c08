// Triangles of two tows' surface meshes that cross: where the meshes of two tows pass through
// each other beyond the loop nodes they share (a chord's sag larger than the gap between two
// nearly tangent surfaces, next to a loop or where tows nearly touch). Per pair of tows whose
// meshes' boxes overlap: their triangles in the common box, then those near a triangle of the
// other (a grid), then box intersection and exact predicates per pair of triangles.
#pragma once

#include <array>
#include <cstddef>
#include <set>
#include <utility>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A triangle of one tow's mesh and one of another's that cross.
struct CrossingTriangles {
    std::size_t towA = 0, triangleA = 0;  ///< towA < towB
    std::size_t towB = 0, triangleB = 0;
};

/// One tow's mesh: node numbers below the caller's ownFrom index the nodes all tows share (loop
/// nodes), the others this tow's own nodes, own[n - ownFrom].
struct TowTriangles {
    const std::vector<std::array<std::size_t, 3>>* triangles = nullptr;
    const std::vector<Point3>* own = nullptr;
};

/// Every crossing pair of triangles of two different tows. Two triangles cross when they meet
/// beyond the shared nodes they have in common: with none, when they intersect at all; with
/// one, when the edge opposite it in either meets the other triangle; with two (an edge), when
/// they are coplanar and lie on the same side of it; three (one triangle of both) never. Tow
/// pairs (a < b) in @p ignored are not tested.
std::vector<CrossingTriangles> crossingTriangles(const std::vector<Point3>& shared, std::size_t ownFrom,
                                                 const std::vector<TowTriangles>& tows,
                                                 const std::set<std::pair<std::size_t, std::size_t>>& ignored, std::size_t threads);

}  // namespace detail
TOWGEOM_END_NAMESPACE
