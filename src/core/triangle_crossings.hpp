// Triangles that cross each other: a tow whose fitted surface folds (it bends sharper than it is
// thick between widely spaced sections), or two surfaces that pass through each other. The
// surface stage looks for folds with it (findFold()), the volume stage names the surfaces when
// Gmsh's tetrahedral mesher stops on crossing triangles.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "towgeom/export.hpp"
#include "towgeom/point.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Two triangles that meet beyond the nodes and edge they share.
struct TriangleCrossing {
    std::size_t surfaceA = 0, surfaceB = 0;  ///< indices into the surfaces given (A <= B)
    Point3 at;                               ///< the centroid of the first crossing pair's first triangle
    std::size_t triangle = 0;                ///< that triangle's index among all triangles given, in order
    std::size_t pairs = 0;                   ///< crossing pairs in all
};

/// Whether any two triangles of @p surfaces (1-based node indices into @p nodes, three per
/// triangle, every triangle on one surface only) cross, by exact predicates:
///  - no node in common: they intersect at all;
///  - one node in common: the edge opposite it in either triangle meets the other triangle;
///  - an edge in common: they lie in one plane on the same side of the edge (fold onto it).
/// Candidates come from CGAL::box_self_intersection_d on the triangles' boxes; the same three
/// nodes twice are passed over. nullopt when no two cross.
std::optional<TriangleCrossing> firstCrossing(const std::vector<Point3>& nodes, const std::vector<const std::vector<std::size_t>*>& surfaces);

}  // namespace detail
TOWGEOM_END_NAMESPACE
