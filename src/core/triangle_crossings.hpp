// Triangles that cross each other: a tow whose fitted surface folds (it bends sharper than it is
// thick between widely spaced sections), or two surfaces that pass through each other. The
// surface stage looks for folds with it (findFold()), the volume stage names the surfaces when
// Gmsh's tetrahedral mesher stops on crossing triangles.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cstddef>
#include <limits>
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

/// Whether triangles @p s and @p t (node numbers; @p ps, @p pt their corners' points) meet beyond
/// the nodes they have in common, by exact predicates (Epick): with none, when they intersect at
/// all; with one, when the edge opposite it in either meets the other triangle; with two (an
/// edge), when they lie in one plane on the same side of it; three (the same triangle) never.
/// Only node numbers below @p sharedBelow can be in common (numbers from it on are each
/// triangle's own). Both triangles must have area (CGAL's tests need their planes).
bool trianglesCross(const std::array<std::size_t, 3>& s, const std::array<CGAL::Epick::Point_3, 3>& ps,
                    const std::array<std::size_t, 3>& t, const std::array<CGAL::Epick::Point_3, 3>& pt,
                    std::size_t sharedBelow = std::numeric_limits<std::size_t>::max());

/// Whether any two triangles of @p surfaces (1-based node indices into @p nodes, three per
/// triangle, every triangle on one surface only) cross, by exact predicates:
///  - no node in common: they intersect at all;
///  - one node in common: the edge opposite it in either triangle meets the other triangle;
///  - an edge in common: they lie in one plane on the same side of the edge (fold onto it).
/// Candidates come from CGAL::box_self_intersection_d on the triangles' boxes; the same three
/// nodes twice, and triangles of no area (collinear corners), are passed over. With @p within
/// not empty only triangles whose boxes meet it are taken. nullopt when no two cross.
std::optional<TriangleCrossing> firstCrossing(const std::vector<Point3>& nodes, const std::vector<const std::vector<std::size_t>*>& surfaces,
                                              const BoundingBox& within = {});

}  // namespace detail
TOWGEOM_END_NAMESPACE
