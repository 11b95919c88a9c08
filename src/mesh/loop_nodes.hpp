// The nodes of an intersection loop that both of its tows' meshes share: the loop resampled at
// the loop spacing, plus the exact points where it crosses either tow's periodic seam.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "towgeom/intersection_loop.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A closed loop's shared nodes, in loop order (the first is not repeated).
struct SharedLoop {
    std::size_t loop = 0;             ///< index in the intersection report
    std::vector<LoopPoint> points;    ///< exact points, (u,v) unwrapped on both tows
    std::vector<std::size_t> nodes;   ///< their global node indices
};

/// One piece of a loop inside a tow's parameter rectangle: a constraint for its mesher.
struct LoopConstraint {
    std::vector<UV> uv;               ///< v within [vMin, vMax]; seam points exactly on vMin or vMax
    std::vector<std::size_t> nodes;   ///< global node of each point
    bool closed = false;              ///< the piece returns to its first point (not repeated)
    /// The intersection loop it is a piece of (-1: none, as a cell's cut). The mesher puts a node
    /// of the tow's own on every edge that joins two nodes of one loop without being its chord.
    long loop = -1;
};

/// Resamples @p loop at @p spacing, adds its exact seam crossings on both tows and appends the
/// points to @p globalNodes.
SharedLoop shareLoopNodes(const IntersectionLoop& loop, std::size_t loopIndex, double spacing,
                          std::vector<Point3>& globalNodes);

/// The two ends of chord @p chord of @p shared (from point chord to the next, the last back to
/// the first), the closing chord's end one turn on if the loop winds around a tow.
std::pair<LoopPoint, LoopPoint> chordEnds(const IntersectionLoop& loop, const SharedLoop& shared, std::size_t chord);

/// The point at fraction @p t of chord @p chord of @p shared, interpolated in 3D and in (u,v)
/// on both tows (not on the curve: a start for Newton's method).
LoopPoint chordPoint(const IntersectionLoop& loop, const SharedLoop& shared, std::size_t chord, double t);

/// True when @p p lies within @p within periods of either tow's seam.
bool onSeam(const IntersectionLoop& loop, const LoopPoint& p, double within);

/// Adds a node on the chord between loop nodes @p a and @p b (consecutive in @p shared) at
/// fraction @p t: the exact loop point where the curve crosses the plane normal to the chord
/// there. Appends it to @p globalNodes. False if a and b are not consecutive, or if the point
/// would leave the chord's period cell on either tow (the curve dips across a seam there) or lie
/// across a tow's rim from the chord (the curve dips onto a cap or back onto the tube).
bool splitChord(const IntersectionLoop& loop, SharedLoop& shared, std::size_t a, std::size_t b, double t,
                std::vector<Point3>& globalNodes);

/// Two loops of one tow pair that touch (lobes of a figure-8 meeting where the surfaces are
/// tangent): when their exact points come within @p within of each other, the touching point (an
/// exact point of @p la there) becomes one node of both: each loop's node nearest to it is
/// replaced by it, so the two loop polygons meet in that node instead of passing a hair's breadth
/// apart. Seam nodes are never replaced. True when the loops were joined.
bool joinTouchingLoops(SharedLoop& a, const IntersectionLoop& la, SharedLoop& b, const IntersectionLoop& lb, double within,
                       std::vector<Point3>& globalNodes);

/// The pieces of @p shared on tow @p side, cut at that tow's seam and shifted into its rectangle.
/// For a loop across the tow's end caps only its pieces on the tube, from rim to rim (rim nodes
/// lie exactly on u = uMin or uMax). Each piece's LoopConstraint::loop is shared.loop.
std::vector<LoopConstraint> constraintsOn(const SharedLoop& shared, const IntersectionLoop& loop, LoopSide side);

/// A piece of a loop on one of a tow's end caps: its global nodes in order, from rim node to rim
/// node (or closed, a loop wholly on the cap).
struct CapConstraint {
    int end = -1;                    ///< -1 the first end's cap (u < uMin), +1 the last's
    std::vector<std::size_t> nodes;  ///< global nodes
    bool closed = false;
};

/// Whether two cap pieces are the same (end, nodes, closed).
inline bool operator==(const CapConstraint& a, const CapConstraint& b) { return a.end == b.end && a.closed == b.closed && a.nodes == b.nodes; }

/// The pieces of @p shared on tow @p side's end caps (none unless the loop crosses a cap there).
std::vector<CapConstraint> capConstraintsOn(const SharedLoop& shared, const IntersectionLoop& loop, LoopSide side);

/// Per tow (of @p towCount), the pieces of every loop in @p shared on its end caps
/// (capConstraintsOn(); @p loops: the intersection report's loops that @p shared index).
std::vector<std::vector<CapConstraint>> capConstraintsOfTows(const std::vector<SharedLoop>& shared, const std::vector<IntersectionLoop>& loops,
                                                             std::size_t towCount);

/// The loop's polygon on tow @p side in unwrapped (u,v), for point-in-polygon tests.
std::vector<UV> loopPolygon(const SharedLoop& shared, LoopSide side);

}  // namespace detail
TOWGEOM_END_NAMESPACE
