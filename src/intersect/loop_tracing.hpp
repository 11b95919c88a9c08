// From one point on an intersection curve to the whole curve: OCCT walks a piece, which ends at
// a periodic seam, a tow's end, or back at its start; at a seam the walk is continued on the
// other side until the curve closes or reaches a tow's end. The pieces are joined with v
// unwrapped; consolidation refines them onto both surfaces and sets the density.
#pragma once

#include <string>
#include <vector>

#include "intersect/intersection_point.hpp"
#include "intersect/surface_walk.hpp"
#include "towgeom/export.hpp"
#include "towgeom/intersection_loop.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Tolerances of a trace, in the user's units.
struct TraceTolerances {
    double point = 1e-7;     ///< largest gap between the two surfaces at a loop point
    double chordal = 1e-4;   ///< largest distance of the curve from a chord between loop points
    double closing = 1e-6;   ///< two piece ends closer than this are the same point
};

/// The sentences of IntersectionLoop::openReason(), one per IntersectionLoop::OpenKind.
namespace open_reason {
constexpr const char* kEndOfA = "the curve reaches an end of the first tow";
constexpr const char* kEndOfB = "the curve reaches an end of the second tow";
constexpr const char* kWalkStops = "the surface-surface walk stops here and cannot be continued (tangent surfaces?)";
constexpr const char* kDoesNotClose = "the curve does not close after many pieces";
}  // namespace open_reason

/// The kind of an open curve's reason (one of open_reason's sentences), or false if
/// @p reason is none of them.
bool openKindOf(const std::string& reason, IntersectionLoop::OpenKind& kind);

/// One traced intersection curve.
struct TracedCurve {
    std::vector<PointOn2> points;  ///< in order, v unwrapped; closed: the first is not repeated
    bool closed = false;
    std::string openReason;        ///< why not closed (empty when closed)
};

/// Traces the curve through @p seed (a point already on the intersection): the walk's points,
/// joined across seams, v unwrapped, each within the point tolerance of both surfaces.
TracedCurve traceCurve(const SurfacePair& surfaces, const SurfaceWalker& walker, const PointOn2& seed,
                       const TraceTolerances& tolerances);

/// A corner of a curve of two closed tows (@p s with its caps): a point exactly on a tow's rim
/// (u equal to the tube's end), where the curve passes from the tube onto the cap. Consolidation
/// keeps such points as they are; false without caps.
bool isCorner(const SurfacePair& s, const PointOn2& p);

/// Refines every point of a traced curve onto both surfaces (to rounding level), drops
/// duplicates, thins the walk's points and densifies to the chordal tolerance.
void consolidateCurve(const SurfacePair& surfaces, TracedCurve& curve, const TraceTolerances& tolerances);

/// Joins open curves whose ends meet (away from tow ends), e.g. the two halves of a loop whose
/// walks both stopped where it grazes a seam; a joined curve whose ends meet becomes closed.
/// Call before consolidateCurve().
void joinOpenCurves(const SurfacePair& surfaces, std::vector<TracedCurve>& curves, const TraceTolerances& tolerances);

/// Drops every curve that runs along another (all its points within twice the chordal
/// tolerance of the other's polyline): the same loop traced from two seeds, where the walks'
/// points strayed too far apart for the checks before tracing to see it. Call after
/// consolidateCurve(), on curves exact to the point tolerance.
void dropDuplicateCurves(std::vector<TracedCurve>& curves, const TraceTolerances& tolerances);

/// Shifts the v of every point of @p piece on both tows by whole periods (@p periodA,
/// @p periodB) so that the piece starts next to @p ref.
void alignPeriods(std::vector<PointOn2>& piece, const PointOn2& ref, double periodA, double periodB);

/// The distance from @p p to the polyline of @p curve (closing segment included when closed).
double distanceToCurve(const TracedCurve& curve, const Point3& p);

/// "Is this point near a curve already traced?" for many points: the curve's segments in runs
/// of 32 with a bounding box each, so that a far point costs one box test per run.
class CurveProximity {
public:
    explicit CurveProximity(const TracedCurve& curve);
    /// True if @p p lies within @p distance of the curve's polyline.
    bool within(const Point3& p, double distance) const;

private:
    const TracedCurve* curve_;
    std::vector<BoundingBox> runs_;
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
