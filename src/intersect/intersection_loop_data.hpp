// The data behind an IntersectionLoop.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "intersect/intersection_point.hpp"
#include "surface/frame.hpp"
#include "towgeom/intersection_loop.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

struct IntersectionLoop::Data {
    Data(TowSurface surfaceA, TowSurface surfaceB) : a(std::move(surfaceA)), b(std::move(surfaceB)) {}
    /// enclosedArea() on both tows, computed once (on first use, by one thread) for this loop.
    struct Areas {
        std::once_flag once;
        std::atomic<bool> done{false};  ///< a and b are set
        double a = 0.0, b = 0.0;        ///< NaN where the loop encloses no area on that tow
    };
    std::size_t towA = 0, towB = 1;
    TowSurface a, b;
    bool closed = false;
    std::string openReason;
    std::vector<LoopPoint> points;
    std::vector<double> cumulative;  ///< arc length at each point (closed: plus the closing segment)
    double tolerance = 1e-7;         ///< the point tolerance the loop was computed with
    double maxDistanceA = 0.0, maxDistanceB = 0.0;
    std::unique_ptr<Areas> areas = std::make_unique<Areas>();
};

namespace detail {

/// The two surfaces of a loop in kernel form (the tubes only).
SurfacePair surfacePairOf(const TowSurface& a, const TowSurface& b);

/// The two closed tows in kernel form: tubes and end caps (SurfacePair::capsA, capsB).
SurfacePair closedPairOf(const TowSurface& a, const TowSurface& b);

/// The sentence saying that loop @p l runs across a tow's end cap (skipped without caps).
std::string crossesCapMessage(const IntersectionLoop& l);

/// The point of tow @p t's closed chart at (u, v): its surface, or its end cap for u beyond the
/// tube's range (cap_chart.hpp).
Point3 closedPoint(const TowSurface& t, double u, double v);

/// closedPoint() with its first derivatives: S_u x S_v points out of the tow on the caps too.
SurfaceDerivatives closedDerivatives(const TowSurface& t, double u, double v);

/// Builds a loop from traced points: fills the arc lengths and distances.
IntersectionLoop makeLoop(std::size_t towA, std::size_t towB, const TowSurface& a, const TowSurface& b,
                          const std::vector<PointOn2>& points, bool closed, const std::string& openReason,
                          double tolerance);

/// @p loop, computed on tows moved into @p frame, as a loop of the user's tows @p a and @p b
/// (the same parameters; points, lengths and tolerances back in the user's units).
IntersectionLoop loopToUser(const IntersectionLoop& loop, const TowSurface& a, const TowSurface& b, const Frame& frame);

/// @p loop, given on the user's tows, on @p a and @p b (those tows moved into @p frame).
IntersectionLoop loopToFrame(const IntersectionLoop& loop, const TowSurface& a, const TowSurface& b, const Frame& frame);

}  // namespace detail

TOWGEOM_END_NAMESPACE
