// Loops that wind around a tow: where a tow passes through another, or ends inside it, their
// intersection loops go around it. Along the tow they cut it into bands, alternately inside and
// outside the other tow; its two end caps lie in the first and the last band.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "mesh/loop_nodes.hpp"
#include "towgeom/intersection_loop.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The loops of one tow pair (t, o) that wind around t, and which bands of t lie inside o.
struct WindingBands {
    std::vector<std::size_t> loops;  ///< indices into the intersection report, by mean u on t (along it)
    bool startInside = false;        ///< t's first band (from u = uMin) and its start cap lie inside o
};

/// The bands that @p winding (loops of the pair (t, o) that wind around tow @p t, by index in
/// @p loops) cut t into. Which side of each loop lies inside o comes from the surfaces: along t
/// (dS_t/du) a loop is crossed into o where that direction points against o's outward normal.
/// nullopt when the loops disagree (a loop whose inside is not the side the alternation gives).
std::optional<WindingBands> windingBands(const std::vector<TowSurface>& tows, std::size_t t, std::size_t o,
                                         const std::vector<IntersectionLoop>& loops, std::vector<std::size_t> winding);

/// A winding loop's node polygon on the tow it goes around (v unwrapped), with its u range.
struct WindingPolygon {
    explicit WindingPolygon(std::vector<UV> polygon);
    std::vector<UV> uv;
    double uLo = 0.0, uHi = 0.0;
};

/// How many of the winding loops @p polygons lie between their tow's start and its point @p p:
/// of each, the parity of its crossings with the segment from (uMin, p.v) to p (a polygon wholly
/// before p in u counts without a test, one wholly after it not).
std::size_t loopsBefore(const std::vector<WindingPolygon>& polygons, UV p, double uMin, double period);

}  // namespace detail
TOWGEOM_END_NAMESPACE
