// Surface triangles that nearly fold onto each other across a shared edge: where two tows touch
// tangentially (pressed flat together) the tows' surfaces meet at their loop at an angle near
// zero, and Gmsh's tetrahedral mesher stops there ("two nearly self-intersecting facets").
// Found before Gmsh is called, so the refusal can name the tows and the place.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "towgeom/export.hpp"
#include "towgeom/point.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Two triangles of different surfaces (or the same one) on one edge, nearly folded together.
struct FacetFold {
    std::size_t surfaceA = 0, surfaceB = 0;  ///< indices into the surfaces given
    Point3 at;                               ///< the middle of the shared edge
    double angle = 0.0;                      ///< the angle between the two triangles around the edge (radians)
};

/// The smallest angle between two triangles on a shared edge, around that edge (0: folded onto
/// each other, pi: in one plane), among the edges whose two nodes both lie on two or more of
/// @p surfaces (the edges where surfaces meet: a loop's, a cap's rim); nullopt if none is below
/// @p tolerance (radians). Triangles of no area (the third node on the edge's line) and edges of
/// no length are passed over. @p surfaces hold 1-based node indices into @p nodes, three per
/// triangle.
std::optional<FacetFold> sharpestFold(const std::vector<Point3>& nodes, const std::vector<const std::vector<std::size_t>*>& surfaces,
                                      double tolerance);

}  // namespace detail
TOWGEOM_END_NAMESPACE
