/// @file shrink_tows.hpp
/// @brief shrinkTows(): the baseline other tools use (TexGen's interference correction, in
/// spirit) — tows shrunk until they no longer interpenetrate, to compare with the shared surfaces.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "towgeom/resolve.hpp"
#include "towgeom/tow_intersection.hpp"
#include "towgeom/tow_stack.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @addtogroup resolution
/// @{

/// The result of shrinkTows().
struct ShrinkResult {
    std::vector<TowSurface> tows;  ///< the shrunk tows, in input order (unchanged ones are the input's)
    std::vector<ShrunkTow> figures;  ///< per tow: scales, volumes, sections
    /// Pairs that still interpenetrate at the smallest scale tried (ShrinkOptions::minScale).
    std::vector<UnresolvedPair> notSeparated;
    std::size_t fits = 0;  ///< trial fits made (two per bisection step with ShrinkOptions::both)
};

/// The shrink baseline: for each tow pair with intersection curves in @p report (in the order of
/// their tow indices), the sections of the lower-ranked tow (ResolveOptions::primaryPatterns,
/// then input order; both tows with ShrinkOptions::both) are scaled about their centroids by
/// 1 - f w(s), w = 1 along the part of the tow the pair's curves span (their u range) and
/// falling to 0 over ShrinkOptions::blendLength on both sides (cos^2), s the length along the
/// polyline of section centroids. f is found by bisection (to ShrinkOptions::tolerance) as the
/// smallest that leaves the refitted pair without an intersection curve and without either tow
/// inside the other or touching it (intersectTows() on the pair: no loop, no finding), so
/// it is known to that tolerance; ShrinkOptions::margin is then added, so the pair keeps a gap
/// its meshes do not close. A section keeps the smallest scale any of its
/// pairs asked for. A pair still interpenetrating (or one inside the other) at f = 1 - minScale
/// is listed in ShrinkResult::notSeparated and not shrunk for that pair (resolveTextile()
/// resolves it by the rank rule). A shrunk tow is
/// refitted with its fit mode and default tolerances. Sections are scaled about the mean of
/// their points: for a section that does not contain that point (a crescent), scaling can move
/// part of it outwards, and new contacts with other tows are not looked for here (resolveTextile()
/// intersects the shrunk tows again and resolves what is left by the rank rule).
///
/// @code
/// const towgeom::IntersectionReport loops = towgeom::intersectTows(tows);
/// const towgeom::ShrinkResult s = towgeom::shrinkTows(tows, loops);
/// for (std::size_t t = 0; t < tows.size(); ++t)
///     std::cout << tows[t].name() << " lost " << s.figures[t].volumeBefore - s.figures[t].volumeAfter
///               << ", largest section change " << s.figures[t].largestSectionChange() << "\n";
/// @endcode
///
/// @throws towgeom::Error (InvalidArgument) for bad options or a report of other tows; (FitFailed)
/// when a shrunk stack cannot be fitted, naming the tow; (Cancelled) through
/// ResolveOptions::monitor.
TOWGEOM_EXPORT ShrinkResult shrinkTows(const std::vector<TowSurface>& tows, const IntersectionReport& report,
                                       const ResolveOptions& options = {});

/// @}

TOWGEOM_END_NAMESPACE
