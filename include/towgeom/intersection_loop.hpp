/// @file intersection_loop.hpp
/// @brief IntersectionLoop: one interpenetration of two tows, as its intersection curve.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "towgeom/curve3.hpp"
#include "towgeom/point.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// Which tow of a pair: A is the first (lower index), B the second.
enum class LoopSide { A, B };

/// A point of an intersection curve with its parameters on both tows. v is unwrapped: it
/// changes continuously along a loop and may lie beyond the period [vMin, vMax).
///
/// Tows are closed solids: a curve that runs into a tow's end continues across that tow's end
/// cap (the planar end section). A point on a cap has a u beyond the tube's range: for the
/// first end u < uMin, for the last u > uMax, and the point is c + rho (S(uEnd, v) - c), c the
/// cap's centre and rho (0 at c, 1 on the rim) growing linearly from the cap's centre out to
/// the rim, where u = uMin (or uMax) and the tube continues. So (u,v) stay continuous along a
/// curve across a cap; IntersectionLoop::crossesCap() says whether a loop does, and
/// TowSurface::pointOnClosed() evaluates such (u,v).
struct LoopPoint {
    Point3 point;  ///< in 3D: the mean of S_A(onA) and S_B(onB), which differ by at most the tolerance
    UV onA;        ///< on tow A
    UV onB;        ///< on tow B
};

/// One interpenetration region of two tows: the curve where their surfaces cross, consolidated
/// into one piece (pieces split at either tow's periodic seam are joined, duplicates dropped).
///
/// A closed loop bounds the region where the tows overlap, on the tows as closed solids: a curve
/// that runs into a tow's end continues across that tow's end cap (crossesCap()), across both
/// caps where both tows end inside each other. An open one (closed() false) is a curve that
/// cannot be closed: both tows end in one plane (caps face to face, a contact), or the
/// surface-surface walk (or the search for the point where it meets a rim) could not continue. Open curves are reported, never dropped or forced
/// shut.
///
/// points() are exact intersection points (refined by Newton's method onto both surfaces),
/// dense enough that the curve stays within the chordal tolerance of the polyline through them.
/// For a closed loop the first point is not repeated at the end.
///
/// Copies are cheap (the data is shared); every member is const and thread-safe.
class TOWGEOM_EXPORT IntersectionLoop {
public:
    /// The loop's data; defined in the library only.
    struct Data;
    /// Used by the library; not needed by callers.
    explicit IntersectionLoop(std::shared_ptr<const Data> data);

    /// Index of tow A in the input of intersectTows() (0 for intersectPair()).
    std::size_t towA() const;
    /// Index of tow B in the input of intersectTows() (1 for intersectPair()).
    std::size_t towB() const;
    /// Tow A's surface.
    const TowSurface& surfaceA() const;
    /// Tow B's surface.
    const TowSurface& surfaceB() const;
    /// True when the curve closes.
    bool closed() const;
    /// Why the curve is open; empty when closed().
    const std::string& openReason() const;
    /// Why a curve is open, typed (openKind()).
    enum class OpenKind {
        None,           ///< the curve is closed
        ReachesEndOfA,  ///< it runs into an end of tow A (A ends inside B, or B crosses A's end)
        ReachesEndOfB,  ///< it runs into an end of tow B
        WalkStops,      ///< the surface-surface walk stops and cannot be continued (tangent surfaces)
        DoesNotClose    ///< the walk goes on but the curve does not close after many pieces
    };
    /// Why the curve is open, typed; OpenKind::None when closed(). openReason() says it in words.
    OpenKind openKind() const;
    /// True when part of the curve runs across an end cap of tow @p side (a point with u beyond
    /// that tow's tube, see LoopPoint): the tow ends inside the other there.
    bool crossesCap(LoopSide side) const;

    /// The dense exact points of the curve, in order.
    const std::vector<LoopPoint>& points() const;
    /// The curve in one tow's (u,v) space, v unwrapped (continuous along the loop).
    std::vector<UV> uvCurve(LoopSide side) const;
    /// The curve in one tow's (u,v) space cut into pieces that lie in its parameter rectangle
    /// (v within [vMin, vMax]): a loop crossing the seam is split there, with an exact
    /// intersection point inserted on the seam at both piece ends (v = vMin on one piece,
    /// vMax on the other). A loop that does not cross the seam gives one piece (closed loops
    /// repeat their first point at the end of it); a loop that winds once around the tow gives
    /// one piece from one side of the seam (vMin or vMax) to the other.
    std::vector<std::vector<UV>> clippedUvCurves(LoopSide side) const;
    /// True when the loop goes once around tow @p side (its unwrapped v changes by a whole
    /// period): it encloses no region on that tow's surface.
    bool windsAround(LoopSide side) const;

    /// The length of the curve (of the polyline through points(), which is within the chordal
    /// tolerance of the curve).
    double length() const;
    /// The area of tow @p side's surface enclosed by a closed loop (integral of |S_u x S_v| over
    /// the loop's (u,v) polygon). NaN for open loops and for loops that wind around the tow.
    double enclosedArea(LoopSide side) const;
    /// The point tolerance the loop was computed with (IntersectionOptions::tolerance, resolved).
    double tolerance() const;
    /// The largest distance of a point of points() from tow @p side's surface (bounded by
    /// |point - S(uv)|); at most the tolerance.
    double maxDistance(LoopSide side) const;

    /// The exact curve point at arc-length fraction @p s (0 <= s <= 1; 0 and 1 are the first
    /// point and, for a closed loop, the first point again; for an open curve, the last).
    LoopPoint at(double s) const;
    /// Exact curve points spaced at most @p spacing apart along the curve (uniform in arc
    /// length, at least 3 intervals for a closed loop). Closed loops do not repeat the first
    /// point; open curves include both ends.
    /// @throws towgeom::Error (InvalidArgument) if @p spacing is not positive and finite, or so
    ///         small that the curve would get more than 1e7 points.
    std::vector<LoopPoint> resample(double spacing) const;
    /// The curve as an evaluable B-spline interpolating points() (periodic when closed); its
    /// parameter is proportional to the arc length of the polyline through points().
    Curve3 curve() const;

    /// The loop's data; for the library's own use.
    const Data& data() const { return *data_; }

private:
    std::shared_ptr<const Data> data_;
};

TOWGEOM_END_NAMESPACE
