// ConnectedRegion: which triangles of a tow's parametric mesh lie inside an intersection loop.
#pragma once

#include <cstddef>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The triangles whose (u,v) centroid (@p centroids, one per triangle; NaN for none, as on a cap)
/// lies inside @p polygon (the loop on this tow, v unwrapped), by CGAL's exact point-in-polygon
/// test. Centroids are tried at v and v shifted by whole periods into the polygon's v range, so
/// loops across the seam work. The loop is a constraint of the mesh, so no triangle straddles it.
std::vector<std::size_t> trianglesInside(const std::vector<UV>& centroids, const std::vector<UV>& polygon, double period);

/// True when @p p (or its copy shifted by whole periods in v) lies strictly inside @p polygon
/// (a loop on a tow, v unwrapped): CGAL's exact point-in-polygon test.
bool insideLoop(const std::vector<UV>& polygon, UV p, double period);

/// True when two loops on one tow (v unwrapped, either copy a whole number of periods apart)
/// cross, touch or lie one inside the other: their regions overlap or meet (exact predicates).
bool loopsMeet(const std::vector<UV>& a, const std::vector<UV>& b, double period);

/// Where two loops on one tow cross: chord k runs from polygon point k to point k + 1 (the
/// last back to the first), t is the fraction along it.
struct LoopCrossing {
    std::size_t chordA = 0, chordB = 0;
    double ta = 0.0, tb = 0.0;
};

/// The crossings of loops @p a and @p b on one tow (v unwrapped, b's copies a whole number of
/// periods apart), by CGAL's exact segment test; chords that end in a node of both (@p nodesA,
/// @p nodesB: the global node of each point) are left out, the loops meet there already.
std::vector<LoopCrossing> loopCrossings(const std::vector<UV>& a, const std::vector<std::size_t>& nodesA,
                                        const std::vector<UV>& b, const std::vector<std::size_t>& nodesB, double period);

}  // namespace detail
TOWGEOM_END_NAMESPACE
