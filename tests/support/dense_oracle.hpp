// The dense oracle of loop detection (issue 38): the same fitted surfaces, tessellated finely and
// intersected by CGAL's surface_intersection, independent of towgeom's intersection code. Every
// curve it finds must be found by towgeom, within the tessellation's chord error.
#pragma once

#include <towgeom/intersection_loop.hpp>
#include <towgeom/tow_intersection.hpp>
#include <towgeom/tow_surface.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace towgeom::testing {

/// A polyline of the oracle: points on both tessellations.
struct OracleCurve {
    std::vector<Point3> points;
    bool closed = false;
    double length = 0.0;
};

/// A tow tessellated finely, and how far its triangles may lie from the surface.
struct DenseTessellation {
    TriangleMesh mesh;
    double chordError = 0.0;  ///< an upper bound: each triangle's and edge's middle against the
                              ///< surface point at the middle of their (u, v)
};

/// @p tow tessellated at @p along x its sections by @p around x its points per section
/// (TowSurface::tessellate: a tube open at its ends).
DenseTessellation denseTessellation(const TowSurface& tow, std::size_t along, std::size_t around);

/// The oracle's curves of one pair and how far they may lie from the exact curves.
struct DenseOracle {
    std::vector<OracleCurve> curves;
    double chordError = 0.0;  ///< the two tessellations' chord errors, summed
};

/// CGAL's intersection of the two tessellations.
DenseOracle denseOracle(const DenseTessellation& a, const DenseTessellation& b);

/// How towgeom's loops of one pair compare with the oracle's curves.
struct OracleComparison {
    std::size_t considered = 0;  ///< oracle curves longer than the minimum length
    std::size_t matched = 0;     ///< of those, curves whose every point lies near one of towgeom's loops
    double longestMissed = 0.0;  ///< length of the longest curve not matched (0: none)
    double farthest = 0.0;       ///< over matched curves, the largest distance of a point to its loop
    std::string missed;          ///< "length L at (x, y, z)" of each curve not matched
};

/// Matches each oracle curve longer than @p minLength with towgeom's @p loops: matched when every
/// point lies within @p within (or a tenth of the curve's length, where near-tangent surfaces
/// magnify the oracle's chord error) of one loop's polyline.
OracleComparison compareWithOracle(const std::vector<OracleCurve>& oracle, const std::vector<IntersectionLoop>& loops,
                                   double minLength, double within);

/// How towgeom's loops of a whole textile compare with the oracle's curves, pair by pair.
struct TextileOracleComparison {
    std::size_t pairs = 0;          ///< tow pairs whose boxes overlap (the oracle ran on these)
    std::size_t considered = 0;     ///< oracle curves longer than 1e-3 of the pair's tow size
    std::size_t matched = 0;        ///< of those, found by towgeom
    double longestMissed = 0.0;     ///< relative to the pair's tow size (0: none missed)
    double farthest = 0.0;          ///< over matched curves, relative to the tow size
    double oracleSeconds = 0.0;     ///< tessellation and CGAL's intersection
    std::string missed;             ///< a line per pair with a missed curve
};

/// compareWithOracle() on every pair of @p tows whose boxes overlap, with their loops in
/// @p report: the oracle tessellates each tow at 8 x its sections by 4 x its points; curves
/// longer than 1e-3 of the smaller tow's size count; a curve is found when every point lies
/// within twice the tessellations' chord error plus 2e-4 of the size of one loop. A pair with a
/// curve not found is compared again at 24 x sections by 12 x points, and that comparison counts.
TextileOracleComparison compareTextileWithOracle(const std::vector<TowSurface>& tows, const IntersectionReport& report);

}  // namespace towgeom::testing
