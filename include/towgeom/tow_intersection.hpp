/// @file tow_intersection.hpp
/// @brief intersectTows(): every interpenetration between the tows of a textile, as loops.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "towgeom/intersection_loop.hpp"
#include "towgeom/intersection_options.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @defgroup intersection Intersecting tows
/// @brief intersectTows(): every interpenetration of the tows as closed IntersectionLoop curves with their (u,v) on both tows (the first stage of resolveTextile()).
/// @{

/// Wall-clock time of the stages of intersectTows(), in milliseconds.
struct IntersectionTimings {
    double broadPhase = 0.0;  ///< span boxes and their overlaps
    double exact = 0.0;       ///< seeds, surface-surface walks, consolidation (all pairs, wall clock)
};

/// A tow pair whose boxes overlap but whose surfaces give no intersection curve, and why.
struct PairFinding {
    /// What was found.
    enum class Kind {
        Touching,  ///< facets cross but the surfaces do not cross along a curve (tangent, coincident)
        Nested,    ///< one tow lies inside the other (no surface crossing, full overlap)
        /// closed curves that enclose no area (thinner than 1e-4 of the tow size): the surfaces
        /// touch along a line (pressed tows); no interpenetration to resolve, so no loop
        Contact,
        /// the search for loops stopped at its budget of patch pairs (surfaces nearly touching
        /// over a wide area): a loop may be missing; the pair is reported unresolved
        Incomplete
    };
    std::size_t towA = 0;  ///< lower tow index
    std::size_t towB = 0;  ///< higher tow index
    Kind kind = Kind::Touching;  ///< what was found
    std::string message;   ///< a sentence naming the tows
};

/// The result of intersectTows().
struct TOWGEOM_EXPORT IntersectionReport {
    /// Every intersection curve, ordered by (towA, towB); within a pair in the order found, which
    /// depends only on the input (not on the number of threads).
    std::vector<IntersectionLoop> loops;
    std::size_t towPairs = 0;         ///< all tow pairs, n (n - 1) / 2
    std::size_t pairsTested = 0;      ///< pairs whose span boxes overlap: the exact stage ran on these
    std::size_t windowPairs = 0;      ///< u-window pairs the exact stage searched
    std::size_t seeds = 0;            ///< crossing facet pairs found in the windows (start guesses)
    std::size_t walks = 0;            ///< surface-surface walks started
    IntersectionTimings timings;      ///< where the time went
    /// Candidate pairs with no curve that nevertheless meet: touching or coincident surfaces,
    /// and tows lying inside others. Not loops (nothing to resolve as a loop); reported so
    /// that such input never passes silently.
    std::vector<PairFinding> findings;
    /// The number of loops with closed() false.
    std::size_t openCount() const;
};

/// Finds every intersection curve between the tows of @p tows.
///
/// 1. Broad phase: a box around each u-span of each surface (from its control points, so it
///    holds the surface) goes into CGAL's box intersection; only tow pairs with overlapping
///    span boxes, and only the u-windows where they overlap, go further. The cost grows with
///    the number of overlapping spans, not with the number of tow pairs.
/// 2. Seeds: within each window pair, both surfaces are faceted on their section grids and
///    CGAL's exact triangle-triangle tests give guesses of curve points.
/// 3. Exact curves: each guess not on a curve already found is refined onto both surfaces and
///    OpenCASCADE's surface-surface intersection walks the curve from there (IntPatch
///    marching); where a walk stops at a periodic seam it is continued on the other side, until
///    the curve closes or runs into a tow's end.
/// 4. Consolidation: pieces are joined with v unwrapped, every point refined onto both
///    surfaces by Newton's method and the polyline densified to the chordal tolerance.
///
/// Limits: the seeds come from facets of a grid on each surface (the input's stations, made at
/// least 48 around and no longer along than twice that): an interpenetration shallower than
/// their chord error can be missed. Surfaces that coincide over an area (identical tows) or meet
/// at a near-tangent angle along a curve (two equal tubes side by side overlapping by ~1e-6 of
/// their size) have no transversal intersection curve the walk can follow, and give no curve.
///
/// @code
/// const towgeom::IntersectionReport r = towgeom::intersectTows(tows);
/// for (const towgeom::IntersectionLoop& l : r.loops)
///     std::cout << tows[l.towA()].name() << " x " << tows[l.towB()].name() << ": "
///               << (l.closed() ? "closed" : l.openReason()) << ", area on A " << l.enclosedArea(towgeom::LoopSide::A) << "\n";
/// for (const towgeom::PairFinding& f : r.findings) std::cerr << f.message << "\n";  // touching, nested
/// towgeom::writeIntersectionReport(r, tows, "loops.json");  // for resolveTextile(tows, report) later
/// @endcode
///
/// @throws towgeom::Error (InvalidArgument) for bad options, (Internal) naming the tow pair if
///         a kernel fails.
TOWGEOM_EXPORT IntersectionReport intersectTows(const std::vector<TowSurface>& tows, const IntersectionOptions& options = {});

/// The intersection curves of two tows (towA() = 0, towB() = 1).
TOWGEOM_EXPORT std::vector<IntersectionLoop> intersectPair(const TowSurface& a, const TowSurface& b,
                                            const IntersectionOptions& options = {});

/// A loop of the host's own: @p points, near the curve where the surfaces of tows @p towA and
/// @p towB cross (from another program, an earlier run, a coarser sampling), each refined onto
/// both surfaces by Newton's method (the intersection point nearest it, on the plane normal to
/// the curve there), with its (u,v) on both tows, v unwrapped along the loop. The result is an
/// IntersectionLoop like intersectTows() makes (openReason() empty, or, for an open polyline,
/// OpenKind::WalkStops), to put into an IntersectionReport for resolveTextile(tows, report).
/// Tolerances as in intersectTows() (@p options; the point tolerance).
///
/// @code
/// towgeom::IntersectionReport mine;
/// mine.loops.push_back(towgeom::intersectionLoopFromPoints(tows, 0, 5, myPolyline, true));
/// const towgeom::ResolveResult r = towgeom::resolveTextile(tows, mine);
/// @endcode
///
/// @throws towgeom::Error (InvalidArgument) naming the point for tow indices that are not two
/// of @p tows (towA < towB), fewer than 3 points (2 for an open polyline), a point that is not
/// finite, that Newton's method cannot bring onto both surfaces, or that lies farther than
/// 0.1 x the smaller tow's size from the curve.
TOWGEOM_EXPORT IntersectionLoop intersectionLoopFromPoints(const std::vector<TowSurface>& tows, std::size_t towA, std::size_t towB,
                                                           const std::vector<Point3>& points, bool closed,
                                                           const IntersectionOptions& options = {});

/// @}

TOWGEOM_END_NAMESPACE
