// The normalised frame of a whole textile (see surface/frame.hpp), and the intersection stage run
// on tows already moved into it: the stages after intersection compute in the same frame.
#pragma once

#include <vector>

#include "surface/frame.hpp"
#include "towgeom/tow_intersection.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The frame a textile is computed in: the box of all tows centred at the origin, the smallest
/// tow's size between 1 and 2.
Frame textileFrame(const std::vector<TowSurface>& tows);

/// @p tows moved into @p frame (detail::inFrame for each).
std::vector<TowSurface> towsInFrame(const std::vector<TowSurface>& tows, const Frame& frame);

/// intersectTows() on tows already in a normalised frame, with options in the frame's units;
/// the loops refer to those tows. With @p region (in the frame), only pairs whose tows' boxes
/// (TowSurface::boundingBox(), which also holds the end caps, grown by the tolerance) overlap
/// inside it are intersected: a loop of any other pair has no point in it. The other pairs give
/// no finding either.
IntersectionReport intersectInFrame(const std::vector<TowSurface>& tows, const IntersectionOptions& options,
                                    const BoundingBox* region = nullptr);

/// intersectTows() (which is this without @p region): the tows moved into their frame,
/// intersected there, the loops given back in the user's units; with @p region (user's units),
/// only the pairs that may meet inside it.
IntersectionReport intersectTowsIn(const std::vector<TowSurface>& tows, const IntersectionOptions& options, const BoundingBox* region);

/// @p report, computed on tows moved into @p frame, for the user's @p tows (loops mapped back).
void reportToUser(IntersectionReport& report, const std::vector<TowSurface>& tows, const Frame& frame);

/// @p report, given for the user's tows, for @p towsInFrame (those tows moved into @p frame).
IntersectionReport reportToFrame(const IntersectionReport& report, const std::vector<TowSurface>& towsInFrame, const Frame& frame);

/// Refuses (InvalidArgument) a report that is not one of @p tows: a loop naming a tow index out
/// of range, or tows other than those at its indices (by name).
void checkReportTows(const std::vector<TowSurface>& tows, const IntersectionReport& report);

/// Refuses (InvalidArgument) negative, zero or non-finite tolerances.
void checkIntersectionOptions(const IntersectionOptions& options);

/// @p options with its absolute lengths moved into @p frame.
IntersectionOptions optionsInFrame(const IntersectionOptions& options, const Frame& frame);

}  // namespace detail
TOWGEOM_END_NAMESPACE
