/// @file intersection_options.hpp
/// @brief Tolerances and run options of tow-tow intersection (intersectTows()).
#pragma once

#include <cstddef>
#include <functional>

#include "towgeom/export.hpp"
#include "towgeom/progress.hpp"

TOWGEOM_BEGIN_NAMESPACE

// The deprecated callback member makes GCC warn in the implicit copy and move members, at this
// definition; only the callback's own uses should warn.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
/// Options for intersectTows() and intersectPair(). Lengths are in the user's units; each
/// tolerance left at 0 is its relative value times the tow size (TowSurface::towSize(), the
/// smaller of the two tows of a pair).
struct IntersectionOptions {
    /// The largest distance of a loop point from either surface. 0 (default): relativeTolerance
    /// times the tow size.
    double tolerance = 0.0;
    /// tolerance relative to the tow size when tolerance is 0. Default 1e-7.
    double relativeTolerance = 1e-7;
    /// The largest distance of the true curve from a chord between consecutive loop points
    /// (the density of IntersectionLoop::points()). 0 (default): relativeChordalTolerance times
    /// the tow size.
    double chordalTolerance = 0.0;
    /// chordalTolerance relative to the tow size when chordalTolerance is 0. Default 1e-4.
    double relativeChordalTolerance = 1e-4;
    /// Worker threads for the exact intersection of candidate pairs; 0 (default) means one per
    /// hardware thread. Results do not depend on it.
    std::size_t threads = 0;
    /// Progress reports ("intersecting tow pairs", pairs done, candidate pairs) and
    /// cancellation (checked before each tow pair); may be null. Not owned: it must outlive the
    /// call.
    Progress* monitor = nullptr;
    /// Called after each candidate tow pair is done, with (pairs done, candidate pairs), from
    /// the calling thread or a worker (never concurrently). May be empty.
    /// @deprecated Use monitor (Progress::update()); removed in 0.3.
    [[deprecated("use IntersectionOptions::monitor (towgeom::Progress); removed in 0.3")]]
    std::function<void(std::size_t, std::size_t)> progress;
};
#pragma GCC diagnostic pop

TOWGEOM_END_NAMESPACE
