// The broad phase of tow intersection: boxes around every u-span of every tow's surface (from
// its control points, so they hold the surface), overlapped with CGAL's box intersection. The
// result says which tow pairs may touch and, within each, which u-windows of the two tows.
#pragma once

#include <cstddef>
#include <vector>

#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// An interval of u on one tow.
struct UWindow {
    double uMin = 0.0;
    double uMax = 0.0;
};

/// A u-window of each tow of a pair whose span boxes overlap.
struct WindowPair {
    UWindow a;
    UWindow b;
};

/// Two tows that may touch (a < b, indices into the input) and where.
struct CandidatePair {
    std::size_t a = 0;
    std::size_t b = 0;
    std::vector<WindowPair> windows;
    std::size_t spanPairs = 0;  ///< overlapping span-box pairs behind the windows
};

/// The candidate pairs of @p tows, in order of (a, b). Boxes are grown by @p margin. Runs of
/// consecutive overlapping spans form a window, widened by one span on each side.
std::vector<CandidatePair> broadPhase(const std::vector<TowSurface>& tows, double margin);

}  // namespace detail
TOWGEOM_END_NAMESPACE
