// Where the tows' meshes cross, the spots to refine them around: both triangles of each crossing
// pair get a smaller size over a disc around them, so that the chords' sag falls below the gap
// between the two surfaces there (next to a loop where they meet at a shallow angle, or where
// they nearly touch).
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "mesh/end_caps.hpp"
#include "mesh/parametric_mesher.hpp"
#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The spots of each tow (empty where its mesh crosses no other) and the crossing triangle pairs
/// of each tow pair (a < b) that has any.
struct CrossingSpots {
    std::vector<std::vector<SizeSpot>> spots;  ///< per tow
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> crossingPairs;
};

/// @p meshes[t] is tow t's mesh from ParametricMesher::result(@p ownFrom): node numbers below
/// @p ownFrom index @p nodes (shared loop nodes), the others its own nodes, @p ownNodes[t][n -
/// ownFrom] in 3D. @p caps, if not empty, holds each tow's end caps as they would be made now
/// (provisionalCaps(), their own nodes numbered on from the tow's: ownFrom + ownNodes[t].size()),
/// tested with the tubes. Tow pairs in @p ignored are not tested (nor in crossingPairs). For each
/// crossing triangle pair of a tow pair that @p refined(pair, its crossing count) accepts, both
/// triangles get a spot at their (u,v) centroid: size half the shorter of the two triangles'
/// longest edges, radius twice the longer. A cap is flat, as exact as it is: of a tube triangle
/// crossing a cap's, the tube's gets a spot by its own longest edge, and the cap's tow one of
/// that size around its own tube node nearest to that triangle, reaching the triangle (refining
/// its end there), unless that node is farther from it than the cap's triangle is long.
CrossingSpots crossingSpots(const std::vector<Point3>& nodes, const std::vector<ParametricMesh>& meshes,
                            const std::vector<std::vector<Point3>>& ownNodes, std::size_t ownFrom, const std::vector<CapMesh>& caps,
                            const std::set<std::pair<std::size_t, std::size_t>>& ignored,
                            const std::function<bool(const std::pair<std::size_t, std::size_t>&, std::size_t)>& refined,
                            std::size_t threads);

}  // namespace detail
TOWGEOM_END_NAMESPACE
