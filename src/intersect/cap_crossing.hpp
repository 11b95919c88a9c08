// Intersection curves across the tows' end caps. A tow is a closed solid: its tube and its two
// planar end caps. A curve of the two tubes that runs into a tow's end continues across that
// tow's cap (the cap's plane against the other tow's surface, by OCCT) and comes back onto the
// tube; the other tow may also pierce a cap without touching the tube there. The pieces on the
// caps get the cap's chart parameters (u beyond the tube's range, cap_chart.hpp), are joined
// with the tubes' open curves and, where both tows end inside each other, with the pieces on both
// caps (cap_cap_segment.hpp); so every curve of two closed tows closes, unless both tows end in
// one plane (caps face to face: a contact, the curve stays open) or a rim point is not found. A
// cap is looked at only when a curve runs into it or the other tow's input points cross its
// plane next to it: one crossed by the other tow's cap alone is not (not handled).
#pragma once

#include <vector>

#include "intersect/loop_tracing.hpp"
#include "towgeom/export.hpp"
#include "towgeom/tow_surface.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Adds the curves on the caps of @p a and @p b to @p curves (traced on the tubes, seams joined)
/// and joins them with the open curves at the rims. The points on a cap are on the closed pair
/// (closedPairOf()) within the point tolerance; consolidate with that pair.
void closeAcrossCaps(const TowSurface& a, const TowSurface& b, std::vector<TracedCurve>& curves, const TraceTolerances& tolerances);

}  // namespace detail
TOWGEOM_END_NAMESPACE
