// Where two tows end inside each other, their end caps cross: the intersection curve of the two
// closed tows runs across both caps along the line where the caps' planes meet. This finds those
// pieces (cap against cap); cap_crossing joins them with the curves on the tubes and on one cap.
#pragma once

#include <vector>

#include "intersect/loop_tracing.hpp"
#include "towgeom/export.hpp"
#include "towgeom/tow_surface.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The pieces of the curve on both @p capA (a cap of @p a) and @p capB (of @p b): the parts of
/// the line where their planes meet that lie inside both rims, each from rim to rim, sampled at
/// most @p step apart, every point refined onto the closed pair @p closed (points on both caps,
/// (ua, va) and (ub, vb) in the caps' charts; the ends exactly on a rim). None when the planes
/// are parallel (caps face to face are a contact, not a crossing).
std::vector<TracedCurve> capCapSegments(const SurfacePair& closed, const TowSurface& a, const CapChart& capA, const TowSurface& b,
                                        const CapChart& capB, double step, const TraceTolerances& tolerances);

}  // namespace detail
TOWGEOM_END_NAMESPACE
